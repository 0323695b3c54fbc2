// Tests of the GL layer that need a context (label `gl`): failures surface as the exceptions of
// gl_error.h with what a user needs to act on them.
#include "gpu/gl_objects.h"

#include <cstdlib>

#include <gtest/gtest.h>

#include "tests/gpu/llvmpipe_suite.h"

#include "gpu/context.h"
#include "gpu/gl_error.h"
#include "gpu/iso_gl.h"

namespace voxref::gpu {
namespace {

class GlObjects : public LlvmpipeSuite {};

TEST_F(GlObjects, ContextIsGl45CoreOnLlvmpipe) {
  EXPECT_EQ(context_->info().renderer.rfind("llvmpipe", 0), 0u);
  EXPECT_GE(context_->info().glMajor * 10 + context_->info().glMinor, 45);
  EXPECT_TRUE(context_->info().supportsPrecise());
  EXPECT_GE(context_->info().max3DTextureSize, 2048);  // GL 4.5's guaranteed minimum
}

TEST_F(GlObjects, CompileErrorsCarryTheLogWithTheSourcesLineNumbers) {
  const char* vs = "void main() { gl_Position = vec4(0.0); }\n";
  const char* fs = "out vec4 c;\nvoid main() {\n  c = vec4(undefinedThing);\n}\n";
  try {
    Program p(context_->gl(), context_->info().glslNumber, vs, fs, "broken.frag");
    FAIL() << "compiled";
  } catch (const ShaderError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.frag (fragment) failed to compile"), std::string::npos);
    EXPECT_NE(e.infoLog().find("undefinedThing"), std::string::npos) << e.infoLog();
    EXPECT_NE(e.infoLog().find("0:3("), std::string::npos) << e.infoLog();  // line 3 of the file, not of the prelude
  }
}

TEST_F(GlObjects, LimitsAndMissingFormatsAreUnsupportedNotErrors) {
  const std::vector<std::uint32_t> codes(3 * 3 * 4097, 0);
  EXPECT_THROW(
      Texture3D(context_->gl(), context_->info().max3DTextureSize, {4097, 3, 3}, ref::TexelFormat::R16, codes, {}),
      GlUnsupported);
  EXPECT_THROW(ColorTarget(context_->gl(), context_->info().maxRenderbufferSize, ref::FramebufferFormat::RGBA12, 8, 8),
               GlUnsupported);
  EXPECT_NO_THROW(
      ColorTarget(context_->gl(), context_->info().maxRenderbufferSize, ref::FramebufferFormat::RGBA16F, 8, 8));
}

TEST_F(GlObjects, ReadBackReturnsStoredCodes) {
  ColorTarget t(context_->gl(), context_->info().maxRenderbufferSize, ref::FramebufferFormat::RGBA8, 4, 2);
  t.bind();
  context_->gl().ClearColor(0.5f, 0.0f, 0.0f, 0.0f);  // 0.5 * 255 = 127.5: stored as 127 or 128
  context_->gl().Clear(GL_COLOR_BUFFER_BIT);
  std::vector<std::uint32_t> codes;
  t.readRedCodes(codes);
  ASSERT_EQ(codes.size(), 8u);
  for (std::uint32_t c : codes) EXPECT_TRUE(c == 127u || c == 128u) << c;
  EXPECT_NO_THROW(checkGl(context_->gl(), "after read-back"));
}

TEST(GlContext, UnknownEglPlatformIsAClearError) {
  setenv("EGL_PLATFORM", "bogus", 1);
  try {
    createContext(Driver::Egl);
    FAIL();
  } catch (const GlUnavailable& e) {
    EXPECT_EQ(std::string(e.what()), "EGL_PLATFORM=bogus is not supported (device or surfaceless)");
  }
  unsetenv("EGL_PLATFORM");
}

TEST(GlContext, DriverNames) {
  EXPECT_EQ(parseDriver("softpipe"), Driver::Softpipe);
  EXPECT_FALSE(parseDriver("vulkan").has_value());
}

// gl_PrimitiveID without a geometry shader (GL 4.6 section 15.2.2): the first triangle of the draw
// is primitive 0, so the mesh program writes id 1 on every pixel of a covering triangle, as the
// control with the constant id does.
TEST_F(GlObjects, PrimitiveIdReachesTheFragmentsOnLlvmpipe) {
  const PrimitiveIdCheck c = checkPrimitiveIdGl(*context_);
  EXPECT_EQ(c.pixels, 256u);
  EXPECT_EQ(c.drawnWithId, 256u);
  EXPECT_EQ(c.rightIds, 256u);
  EXPECT_EQ(c.drawnByControl, 256u);
  EXPECT_FALSE(c.driverDropsPrimitiveIdDraws());
}

}  // namespace
}  // namespace voxref::gpu
