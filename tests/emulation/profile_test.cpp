#include "emulation/profile.h"

#include <set>

#include <gtest/gtest.h>

namespace voxref::emu {
namespace {

TEST(Profiles, NamesAreUniqueAndFindable) {
  std::set<std::string_view> names;
  for (const PrecisionProfile& p : knownProfiles()) {
    EXPECT_TRUE(names.insert(p.name).second) << p.name;
    EXPECT_EQ(findProfile(p.name), &p);
    EXPECT_FALSE(p.summary.empty());
  }
  EXPECT_EQ(findProfile("radeonsi"), nullptr);
}

TEST(AutoProfile, FollowsRendererEnvironmentAndCpu) {
  const std::string_view lp = "llvmpipe (LLVM 15.0.6, 256 bits)";
  EXPECT_EQ(autoProfile(lp, "", "", true)->name, "llvmpipe");
  EXPECT_EQ(autoProfile(lp, "", "", false)->name, "llvmpipe-nofma");
  EXPECT_EQ(autoProfile(lp, "", "sse4.1", true)->name, "llvmpipe-nofma");
  EXPECT_EQ(autoProfile(lp, "no_aos_sampling", "", true)->name, "llvmpipe-noaos");
  EXPECT_EQ(autoProfile(lp, "no_filter_hacks,no_aos_sampling", "sse4.1", true)->name, "llvmpipe-noaos-nofma");
  EXPECT_EQ(autoProfile("softpipe", "", "", true)->name, "softpipe");
  EXPECT_EQ(autoProfile("AMD Radeon RX 7600 (radeonsi, navi33)", "", "", true), nullptr);
}

TEST(Departures, SoftpipeNamesItsTwoAndLlvmpipeNone) {
  EXPECT_TRUE(departuresFromGlSemantics(*findProfile("llvmpipe")).empty());
  const auto d = departuresFromGlSemantics(*findProfile("softpipe"));
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].id, "softpipe.framebuffer.no_per_pass_requantization");
  EXPECT_TRUE(d[0].flushEachPass);
  EXPECT_EQ(d[1].id, "softpipe.texture.tile_cache_aliasing");
  EXPECT_FALSE(d[1].semantics.textureTileCache.aliasing);
}

TEST(Departures, OnlyThoseAScenesEffectsMeet) {
  const PrecisionProfile& sp = *findProfile("softpipe");
  const Effect nearestAlphaBlend[] = {Effect::SamplerNearest, Effect::FloatTileCache, Effect::BlendAlphaFloat};
  const auto d = departuresAmong(sp, nearestAlphaBlend);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].id, "softpipe.framebuffer.no_per_pass_requantization");
  const Effect linearOnly[] = {Effect::SamplerFloatWeights, Effect::TileCacheAliasing};
  ASSERT_EQ(departuresAmong(sp, linearOnly).size(), 1u);
  EXPECT_EQ(departuresAmong(sp, linearOnly)[0].id, "softpipe.texture.tile_cache_aliasing");
  EXPECT_TRUE(departuresAmong(sp, std::span<const Effect>{}).empty());
}

}  // namespace
}  // namespace voxref::emu
