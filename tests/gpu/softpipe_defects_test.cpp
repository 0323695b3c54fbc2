// The softpipe defects voxref reports as findings, shown on the driver itself (docs/profiles.md).
// Its own executable: OSMesa picks its gallium driver once per process, and these need softpipe.
#include <gtest/gtest.h>

#include "gpu/context.h"
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

}  // namespace
}  // namespace voxref::gpu
