#include "emulation/combination_envelope.h"

#include <algorithm>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "emulation/combination_emu.h"
#include "reference/common/fields.h"
#include "reference/common/framebuffer_codes.h"
#include "reference/sparsegrid/combination.h"

namespace voxref::emu {
namespace {

MeasuredArithmetic fromValues(std::map<std::string, std::string> values) {
  return measuredArithmetic([&](const char* id) { return values[id]; });
}

// llvmpipe's probe values (docs/probe.md, "Measured"): float filtering, nearest stores, every pass stored.
const std::map<std::string, std::string> kLlvmpipe{{"sampling.float.subtexel_bits", "float"},
                                                   {"sampling.float.lerp", "fused"},
                                                   {"store.unorm8_rounding", "half_even"},
                                                   {"framebuffer.between_passes", "requantized"}};

TEST(MeasuredArithmetic, OnlyDeterminedPropertiesCount) {
  const MeasuredArithmetic lp = fromValues(kLlvmpipe);
  EXPECT_TRUE(lp.floatFiltering);
  EXPECT_EQ(lp.unorm8Store, MeasuredArithmetic::Store::Nearest);
  EXPECT_TRUE(lp.any());
  auto tile = kLlvmpipe;
  tile["framebuffer.between_passes"] = "float_tile_cache";  // softpipe: no per-pass store to rely on
  EXPECT_EQ(fromValues(tile).unorm8Store, MeasuredArithmetic::Store::Spec);
  auto unknown = kLlvmpipe;
  unknown["sampling.float.lerp"] = "unknown";
  unknown["store.unorm8_rounding"] = "floor";
  EXPECT_FALSE(fromValues(unknown).floatFiltering);
  EXPECT_EQ(fromValues(unknown).unorm8Store, MeasuredArithmetic::Store::Floor);
  EXPECT_FALSE(fromValues({}).any());
}

struct Scene {
  ref::Combination combination;
  ref::CombinationTextures textures;
  ref::PlaneFrame frame = ref::orbitFrame(30, 20, 24, 24, 12);
  explicit Scene(int level)
      : combination(ref::SparseGrid::fromField({level, true}, ref::analyticField("gaussian_blobs"))),
        textures(ref::buildCombinationTextures(combination, {})) {}
};

// The measured envelope lies inside the spec's at every sample (each of its rules is a special case
// of the spec's), holds llvmpipe's emulation (whose arithmetic the measurements describe), and at
// level 6, where the spec's envelope is blind, its widest interval is far below the data's spread.
TEST(MeasuredCombinationEnvelope, InsideTheSpecsHoldsTheDriverAndSeesAtLevel6) {
  const Scene s(6);
  const CombinationEnvelope spec(s.textures, s.frame, {}, ref::FramebufferFormat::RGBA8);
  const CombinationEnvelope measured(s.textures, s.frame, {}, ref::FramebufferFormat::RGBA8, fromValues(kLlvmpipe));
  EXPECT_EQ(spec.basis(), "spec");
  EXPECT_EQ(measured.basis(), "measured float filtering, measured nearest 8-bit stores");
  EXPECT_LT(measured.colourThreshold(), spec.colourThreshold());
  const auto emulated =
      emulateCombination(s.textures, s.frame, {}, ref::FramebufferFormat::RGBA8, *findProfile("llvmpipe"));
  double widestSpec = 0, widestMeasured = 0, lo = 1, hi = 0;
  for (int k = 0; k < s.frame.planes; ++k)
    for (int j = 0; j < s.frame.height; ++j)
      for (int i = 0; i < s.frame.width; ++i) {
        const Interval a = spec.at(i, j, k, spec.passPrecision()), b = measured.at(i, j, k, measured.passPrecision());
        ASSERT_GE(b.lo, a.lo);
        ASSERT_LE(b.hi, a.hi);
        const double v = ref::decodeFramebufferCode(
            ref::FramebufferFormat::RGBA8,
            emulated.planes.codes[i + static_cast<std::size_t>(s.frame.width) * (j + s.frame.height * k)]);
        ASSERT_TRUE(b.contains(v)) << i << " " << j << " " << k;
        widestSpec = std::max(widestSpec, a.hi - a.lo);
        widestMeasured = std::max(widestMeasured, b.hi - b.lo);
        lo = std::min(lo, v), hi = std::max(hi, v);
      }
  EXPECT_GE(widestSpec, hi - lo);          // blind
  EXPECT_LT(4 * widestMeasured, hi - lo);  // sees
}

// A driver that stores by floor is held to the floor: llvmpipe's round-to-nearest emulation leaves it.
TEST(MeasuredCombinationEnvelope, AWrongStoreRuleFails) {
  const Scene s(4);
  auto floor = kLlvmpipe;
  floor["store.unorm8_rounding"] = "floor";
  const CombinationEnvelope measured(s.textures, s.frame, {}, ref::FramebufferFormat::RGBA8, fromValues(floor));
  const auto emulated =
      emulateCombination(s.textures, s.frame, {}, ref::FramebufferFormat::RGBA8, *findProfile("llvmpipe"));
  std::size_t outside = 0;
  for (int k = 0; k < s.frame.planes; ++k)
    for (int j = 0; j < s.frame.height; ++j)
      for (int i = 0; i < s.frame.width; ++i)
        outside +=
            !measured.at(i, j, k, measured.passPrecision())
                 .contains(ref::decodeFramebufferCode(
                     ref::FramebufferFormat::RGBA8,
                     emulated.planes.codes[i + static_cast<std::size_t>(s.frame.width) * (j + s.frame.height * k)]));
  EXPECT_GT(outside, 0u);
}

// What a blind case says: each stage still bounded by the spec's rule, with why no measurement replaces it.
TEST(MeasuredCombinationEnvelope, NamesTheStagesLeftAtTheSpecsRules) {
  const Scene s(3);
  EXPECT_NE(CombinationEnvelope(s.textures, s.frame, {}, ref::FramebufferFormat::RGBA8)
                .specStages()
                .find("no measured arithmetic"),
            std::string::npos);
  EXPECT_EQ(
      CombinationEnvelope(s.textures, s.frame, {}, ref::FramebufferFormat::RGBA8, fromValues(kLlvmpipe)).specStages(),
      "");
  const std::string rgba12 =
      CombinationEnvelope(s.textures, s.frame, {}, ref::FramebufferFormat::RGBA12, fromValues(kLlvmpipe)).specStages();
  EXPECT_EQ(rgba12, "the 12-bit store (the probe measures 8-bit stores only)");
  const std::string half =
      CombinationEnvelope(s.textures, s.frame, {}, ref::FramebufferFormat::RGBA16F, fromValues(kLlvmpipe)).specStages();
  EXPECT_NE(half.find("float blend"), std::string::npos);
  ref::CombinationTextures r8 = s.textures;
  r8.format = ref::TexelFormat::R8;
  EXPECT_NE(CombinationEnvelope(r8, s.frame, {}, ref::FramebufferFormat::RGBA8, fromValues(kLlvmpipe))
                .specStages()
                .find("8-bit texture"),
            std::string::npos);
}

}  // namespace
}  // namespace voxref::emu
