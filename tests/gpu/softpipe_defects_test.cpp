// The softpipe defects voxref reports as findings, shown on the driver itself (docs/profiles.md),
// and a limit of softpipe that voxref must report rather than work around. Its own executable:
// OSMesa picks its gallium driver once per process, and these need softpipe.
#include <gtest/gtest.h>

#include <string>

#include "gpu/context.h"
#include "gpu/gl_error.h"
#include "gpu/iso_gl.h"

namespace voxref::gpu {
namespace {

// A fragment shader that reads gl_PrimitiveID with no geometry shader bound draws nothing on
// softpipe (no colour, no depth, no GL error), while the same program writing a constant id draws
// every pixel: the cause of the black iso images (finding
// gl.fragment.primitive_id_without_geometry_shader_drops_fragments).
TEST(SoftpipeDefects, AFragmentShaderReadingPrimitiveIdDrawsNothing) {
  const auto context = createContext(Driver::Softpipe);
  ASSERT_EQ(context->info().renderer.rfind("softpipe", 0), 0u) << context->info().renderer;
  const PrimitiveIdCheck c = checkPrimitiveIdGl(*context);
  EXPECT_EQ(c.pixels, 256u);
  EXPECT_EQ(c.drawnByControl, 256u);
  EXPECT_EQ(c.drawnWithId, 0u);
  EXPECT_TRUE(c.driverDropsPrimitiveIdDraws());
}

// Softpipe's GLSL 3.30 has no storage buffers: the buffer counter is refused with its reason,
// never replaced by the queries, and the queries still count.
TEST(SoftpipeLimits, TheBufferCounterIsRefusedWithItsReason) {
  const auto context = createContext(Driver::Softpipe);
  const std::string problem = sampleCounterProblem(*context, SampleCounter::Buffer);
  EXPECT_NE(problem.find("needs GLSL 4.30"), std::string::npos) << problem;
  EXPECT_EQ(sampleCounterProblem(*context, SampleCounter::Queries), "");
  ref::ViewCamera c;
  c.eye = {0.0, 0.0, 10.0};
  c.width = c.height = 16;
  const std::vector<QueryBox> box = {{{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}}};
  EXPECT_THROW(occlusionQueriesGl(*context, ref::IsoMesh{}, box, c, SampleCounter::Buffer), GlUnsupported);
  const std::vector<std::uint32_t> counted = occlusionQueriesGl(*context, ref::IsoMesh{}, box, c);
  ASSERT_EQ(counted.size(), 1u);
  EXPECT_GT(counted[0], 0u);
}

}  // namespace
}  // namespace voxref::gpu
