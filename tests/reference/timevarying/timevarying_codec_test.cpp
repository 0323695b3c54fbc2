#include "reference/timevarying/timevarying_codec.h"

#include <bit>
#include <random>
#include <set>

#include <cmath>

#include <gtest/gtest.h>

#include "reference/timevarying/plume.h"

namespace voxref::ref {
namespace {

const IndexEncoding kEncodings[] = {IndexEncoding::NormalizedRgba8, IndexEncoding::NormalizedRgba16,
                                    IndexEncoding::NormalizedFloat, IndexEncoding::BlockRgba8};

// The input after the transfer function, voxel by voxel: what the decoder must reproduce.
std::vector<Rgba8> expected(const TimeSeries& s, const TransferFunction& tf, int t) {
  std::vector<Rgba8> out;
  const auto& v = s.steps[static_cast<std::size_t>(t)];
  for (int z = 0; z < s.original[2]; ++z)
    for (int y = 0; y < s.original[1]; ++y)
      for (int x = 0; x < s.original[0]; ++x)
        out.push_back(tf(v[static_cast<std::size_t>(x) +
                           static_cast<std::size_t>(s.side) * (y + static_cast<std::size_t>(s.side) * z)]));
  return out;
}

void expectLossless(const TimeSeries& s, const TransferFunction& tf, const TimeVaryingOptions& o) {
  const TimeVaryingTextures tex = encodeTimeVarying(s, tf, o);
  for (int t = 0; t < static_cast<int>(s.steps.size()); ++t)
    ASSERT_EQ(decodeStep(tex, t), expected(s, tf, t)) << "step " << t << " level " << o.level;
}

TEST(TimeVaryingCodec, RoundTripIsLosslessOnEveryStepLevelAndEncoding) {
  const TimeSeries plume = dischargePlume({32, 10, 400.0});
  EXPECT_LT(sparseness(plume), 0.999);  // not trivially empty
  for (IndexEncoding e : kEncodings)
    for (int level = 1; level <= 3; ++level) expectLossless(plume, transferFunction("plume"), {level, e});
}

TEST(TimeVaryingCodec, StatisticsAddUp) {
  const TimeSeries plume = dischargePlume({32, 10, 400.0});
  const TimeVaryingTextures tex = encodeTimeVarying(plume, transferFunction("plume"), {2});
  const EncodeStats& st = tex.stats;
  EXPECT_EQ(st.homogeneousCells + st.refinedCells, 10u * 4 * 4 * 4);
  EXPECT_EQ(st.hashHits + st.distinctBlocks, st.refinedCells);  // every refined cell is a new block or a shared one
  EXPECT_EQ(st.indexBytes, 10u * 4 * 4 * 4 * 4);                // T n^3 RGBA8 texels, as the paper counts
  EXPECT_EQ(st.refinementBytes, st.distinctBlocks * 8 * 8 * 8 * 4);
  EXPECT_EQ(st.ratioAgainst4Bytes(), 4.0 * 10 * 32 * 32 * 32 / double(st.indexBytes + st.refinementBytes));
  EXPECT_EQ(tex.layout.indexSlots, 4);  // smallest power of two with S^3 >= 10
}

TEST(TimeVaryingCodec, PapersTable2CountsFollowFromItsDefinitions) {
  // Table 2's "cells" are bytes: 36 steps x n^3 index texels x 4. Level 4: 36 * 16^3 * 4 = 589824.
  for (const auto& [level, bytes] : {std::pair{3, 73728u}, std::pair{4, 589824u}, std::pair{5, 4718592u}}) {
    TimeSeries empty;
    empty.side = 128;
    empty.original = {128, 128, 128};
    empty.steps.assign(36, std::vector<std::uint8_t>(128 * 128 * 128, 0));
    EXPECT_EQ(encodeTimeVarying(empty, transferFunction("plume"), {level}).stats.indexBytes, bytes);
  }
}

TEST(TimeVaryingCodec, FlagCollisionBreaksThePaperPolicyOnly) {
  // A homogeneous cell of value 230: the "opaque" transfer function gives it alpha 255, the flag.
  TimeSeries s;
  s.side = 16;
  s.original = {16, 16, 16};
  s.steps.assign(1, std::vector<std::uint8_t>(16 * 16 * 16, 0));
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) s.steps[0][x + 16 * (y + 16 * z)] = 230;
  s.steps[0][15 + 16 * (15 + 16 * 15)] = 7;  // one refined cell, so that a refinement texture exists
  const TransferFunction tf = transferFunction("opaque");
  ASSERT_EQ(tf(230)[3], 255);
  const TimeVaryingTextures paper =
      encodeTimeVarying(s, tf, {1, IndexEncoding::NormalizedRgba8, AlphaOnePolicy::Paper});
  EXPECT_EQ(paper.stats.alphaOneCells, 1u);
  bool wrong = false;
  try {
    wrong = decodeStep(paper, 0) != expected(s, tf, 0);
  } catch (const std::out_of_range&) {
    wrong = true;  // the colour read as an address points outside the refinement texture
  }
  EXPECT_TRUE(wrong);
  expectLossless(s, tf, {1, IndexEncoding::NormalizedRgba8, AlphaOnePolicy::Refine});
}

TEST(TimeVaryingCodec, HashCollisionsAreCaughtByTheFullComparison) {
  const TimeSeries plume = dischargePlume({32, 10, 400.0});
  TimeVaryingOptions weak{2};
  weak.hashBits = 2;  // four hash values: most distinct blocks collide
  const auto strong = encodeTimeVarying(plume, transferFunction("plume"), {2});
  const auto collided = encodeTimeVarying(plume, transferFunction("plume"), weak);
  EXPECT_GT(collided.stats.hashCollisions, 10u);
  EXPECT_EQ(strong.stats.hashCollisions, 0u);
  EXPECT_EQ(collided.stats.distinctBlocks, strong.stats.distinctBlocks);  // nothing merged wrongly
  expectLossless(plume, transferFunction("plume"), weak);
}

TEST(TimeVaryingCodec, EmptyAndFullStepsRoundTrip) {
  TimeSeries s;
  s.side = 16;
  s.original = {16, 16, 16};
  std::mt19937 rng(5);
  std::vector<std::uint8_t> full(16 * 16 * 16);
  for (auto& v : full) v = static_cast<std::uint8_t>(1 + rng() % 255);  // every voxel non-zero
  s.steps = {std::vector<std::uint8_t>(full.size(), 0), full};
  const auto tex = encodeTimeVarying(s, transferFunction("gray"), {2});
  EXPECT_EQ(tex.stats.homogeneousCells, 64u);  // the empty step
  EXPECT_EQ(tex.stats.refinedCells, 64u);      // the noisy one
  for (IndexEncoding e : kEncodings) expectLossless(s, transferFunction("gray"), {2, e});
}

TEST(TimeVaryingCodec, CapacityExceededIsAClearError) {
  const TimeSeries plume = dischargePlume({32, 10, 400.0});
  TimeVaryingOptions o{3};
  o.maxTextureExtent = 8;
  try {
    encodeTimeVarying(plume, transferFunction("plume"), o);
    FAIL();
  } catch (const CapacityError& e) {
    EXPECT_NE(std::string(e.what()).find("texels per axis"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("the limit is 8"), std::string::npos) << e.what();
  }
  EXPECT_THROW(encodeTimeVarying(plume, transferFunction("plume"), {5}),
               std::invalid_argument);  // blocks of one voxel: level > log2(32) - 1
  EXPECT_THROW(encodeTimeVarying(plume, transferFunction("plume"), {0}), std::invalid_argument);
}

TEST(TimeVaryingLayout, PapersEquationOneDoesNotAddressManySteps) {
  // 8 index slots per axis (level 4 of a 128^3 texture, d_i = 8, d_r = 16 texels per slot).
  // Equation (1) puts z at (t mod 64) d_r: for t >= 8 it lies outside the 8-slot texture, and
  // y = (t div 8) d_r leaves it for t >= 64. voxref's layout keeps all 512 slots distinct and inside.
  int insidePaper = 0;
  std::set<std::array<int, 3>> ours;
  TimeVaryingLayout l;
  l.indexSlots = 8;
  for (int t = 0; t < 512; ++t) {
    const auto o = paperIndexOrigin(t, 8, 16);
    insidePaper += o[0] < 128 && o[1] < 128 && o[2] < 128;
    const auto s = indexSlot(l, t);
    EXPECT_TRUE(s[0] < 8 && s[1] < 8 && s[2] < 8);
    ours.insert(s);
  }
  EXPECT_EQ(insidePaper, 8);
  EXPECT_EQ(ours.size(), 512u);
}

// The textures as stored (unused slots included) are what a file holds: auto stores the fewest
// (the file sizes themselves: TimeVaryingContainer.AutoLevelWritesTheSmallestFile).
TEST(TimeVaryingCodec, AutoLevelStoresTheFewestTextureBytes) {
  const TimeSeries plume = dischargePlume({32, 10, 400.0});
  const auto best = encodeTimeVaryingAutoLevel(plume, transferFunction("plume"), {});
  for (int level = 1; level <= 3; ++level) {
    const auto t = encodeTimeVarying(plume, transferFunction("plume"), {level});
    EXPECT_LE(best.stats.indexBytesAllocated + best.stats.refinementBytesAllocated,
              t.stats.indexBytesAllocated + t.stats.refinementBytesAllocated);
  }
}

TEST(PadToCube, PadsExplicitlyAndKeepsTheOriginalExtents) {
  Volume<std::uint8_t> v({37, 5, 11}, 9);
  v.at(36, 4, 10) = 200;
  const TimeSeries s = padToCube({v, v});
  EXPECT_EQ(s.side, 64);
  EXPECT_EQ(s.original, (Dims3{37, 5, 11}));
  expectLossless(s, transferFunction("gray"), {3});
  EXPECT_THROW(padToCube({v, Volume<std::uint8_t>({37, 5, 12})}), std::invalid_argument);
  EXPECT_THROW(padToCube({Volume<std::uint8_t>({513, 2, 2})}), std::invalid_argument);
}

TEST(DischargePlume, DeterministicAndOnTarget) {
  EXPECT_EQ(dischargePlume({32, 6, 300.0}).steps, dischargePlume({32, 6, 300.0}).steps);
  double got = 0.0;
  const TimeSeries s = dischargePlumeWithSparseness({32, 6}, 0.997, &got);
  EXPECT_NEAR(got, 0.997, 0.0005);
  EXPECT_EQ(sparseness(s), got);
}

// The sparseness search simulates the field once; it must give the very series of the plain
// bisection that generates the whole plume at every gain it tries (the definition).
TEST(DischargePlume, SparsenessSearchEqualsTheBisectionOverWholePlumes) {
  for (const double target : {0.99, 0.997}) {
    PlumeOptions o{32, 5};
    double lo = -4.0, hi = 20.0;
    for (int i = 0; i < 26; ++i) {
      const double mid = 0.5 * (lo + hi);
      o.gain = std::exp2(mid);
      (sparseness(dischargePlume(o)) > target ? lo : hi) = mid;
    }
    o.gain = std::exp2(hi);
    EXPECT_EQ(dischargePlumeWithSparseness({32, 5}, target).steps, dischargePlume(o).steps) << target;
  }
}

}  // namespace
}  // namespace voxref::ref
