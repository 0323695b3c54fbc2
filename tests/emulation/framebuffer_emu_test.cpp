#include "emulation/framebuffer_emu.h"

#include <gtest/gtest.h>

namespace voxref::emu {
namespace framebuffer_emu_test {  // named: a unity build compiles several test files together

using ref::BlendEquation;
using ref::FramebufferFormat;

std::uint32_t blendAll(FramebufferFormat f, const PrecisionProfile& p, bool flush,
                       std::initializer_list<std::pair<float, BlendEquation>> passes) {
  const BlendEmu b(f, p, flush, 8, 8);
  PixelState px = b.cleared();
  for (const auto& [src, eq] : passes) b.blend(px, src, eq);
  return b.resolve(px);
}

const PrecisionProfile& llvmpipe() { return *findProfile("llvmpipe"); }
const PrecisionProfile& softpipe() { return *findProfile("softpipe"); }

// Expected values below were measured on Mesa 22.3.6 (docs/precision.md and the research note).
TEST(BlendEmu, TenSmallAddsVanishPerPassButNotInATileCache) {
  const float s = 0.0019f;  // 0.0019 * 255 = 0.4845 -> 0 per pass
  auto ten = [&](const PrecisionProfile& p, bool flush) {
    const BlendEmu b(FramebufferFormat::RGBA8, p, flush, 8, 8);
    PixelState px = b.cleared();
    for (int i = 0; i < 10; ++i) b.blend(px, s, BlendEquation::FuncAdd);
    return b.resolve(px);
  };
  EXPECT_EQ(ten(llvmpipe(), false), 0u);  // llvmpipe: 0
  EXPECT_EQ(ten(softpipe(), false), 5u);  // softpipe: 0.019 * 255 = 4.845 -> 5
  EXPECT_EQ(ten(softpipe(), true), 0u);   // softpipe with glFinish after every draw: 0
}

TEST(BlendEmu, SaturatingFixedPoint) {
  EXPECT_EQ(blendAll(FramebufferFormat::RGBA8, llvmpipe(), false,
                     {{0.9f, BlendEquation::FuncAdd}, {0.9f, BlendEquation::FuncAdd}}),
            255u);
  EXPECT_EQ(blendAll(FramebufferFormat::RGBA8, llvmpipe(), false, {{0.5f, BlendEquation::FuncReverseSubtract}}), 0u);
  EXPECT_EQ(blendAll(FramebufferFormat::RGBA8, softpipe(), false,
                     {{0.9f, BlendEquation::FuncAdd}, {0.9f, BlendEquation::FuncAdd}}),
            255u);
  // dst - src, not src - dst: 200/255 - 100/255.
  EXPECT_EQ(blendAll(FramebufferFormat::RGBA8, llvmpipe(), false,
                     {{200 / 255.0f, BlendEquation::FuncAdd}, {100 / 255.0f, BlendEquation::FuncReverseSubtract}}),
            100u);
  EXPECT_EQ(blendAll(FramebufferFormat::RGBA12, llvmpipe(), false, {{0.5f, BlendEquation::FuncAdd}}),
            2048u);  // 2047.5: even
}

TEST(BlendEmu, HalfFloatAccumulation) {
  auto tenAdds = [&](const PrecisionProfile& p, float v) {
    const BlendEmu b(FramebufferFormat::RGBA16F, p, false, 8, 8);
    PixelState px = b.cleared();
    for (int i = 0; i < 10; ++i) b.blend(px, v, BlendEquation::FuncAdd);
    return b.resolve(px);
  };
  // Measured: 10 x ADD (0.1, 1.7, -0.3): llvmpipe 3bfb 4c3e c1fd (toward zero every pass);
  // softpipe without flushes 3c00 4c40 c1ff (float32 sum, toward zero once).
  EXPECT_EQ(tenAdds(llvmpipe(), 0.1f), 0x3bfbu);
  EXPECT_EQ(tenAdds(llvmpipe(), 1.7f), 0x4c3eu);
  EXPECT_EQ(tenAdds(llvmpipe(), -0.3f), 0xc1fdu);
  EXPECT_EQ(tenAdds(softpipe(), 0.1f), 0x3c00u);
  EXPECT_EQ(tenAdds(softpipe(), 1.7f), 0x4c40u);
  EXPECT_EQ(tenAdds(softpipe(), -0.3f), 0xc1ffu);
}

TEST(BlendEmu, Unorm16StoreRounding) {
  const float x = 0x1.0001p-17f;  // measured: llvmpipe 0, softpipe 1
  EXPECT_EQ(blendAll(FramebufferFormat::RGBA16, llvmpipe(), false, {{x, BlendEquation::FuncAdd}}), 0u);
  EXPECT_EQ(blendAll(FramebufferFormat::RGBA16, softpipe(), false, {{x, BlendEquation::FuncAdd}}), 1u);
}

TEST(BlendEmu, Float32KeepsNegativesAndFlushesDenormalsOnLlvmpipe) {
  const std::uint32_t code =
      blendAll(FramebufferFormat::RGBA32F, llvmpipe(), false, {{0.25f, BlendEquation::FuncReverseSubtract}});
  EXPECT_EQ(std::bit_cast<float>(code), -0.25f);
  EXPECT_EQ(std::bit_cast<float>(
                blendAll(FramebufferFormat::RGBA32F, llvmpipe(), false, {{0x1p-130f, BlendEquation::FuncAdd}})),
            0.0f);
  EXPECT_EQ(std::bit_cast<float>(
                blendAll(FramebufferFormat::RGBA32F, softpipe(), false, {{0x1p-130f, BlendEquation::FuncAdd}})),
            0x1p-130f);
}

TEST(BlendEmu, RefusesTargetsTheTileCacheModelDoesNotCover) {
  EXPECT_THROW(BlendEmu(FramebufferFormat::RGBA8, softpipe(), false, 384, 128), std::invalid_argument);
  EXPECT_NO_THROW(BlendEmu(FramebufferFormat::RGBA8, softpipe(), false, 320, 640));
  EXPECT_NO_THROW(BlendEmu(FramebufferFormat::RGBA8, llvmpipe(), false, 4096, 4096));
}

}  // namespace framebuffer_emu_test
}  // namespace voxref::emu
