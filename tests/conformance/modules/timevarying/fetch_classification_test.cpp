#include "conformance/modules/timevarying/fetch_classification.h"

#include <gtest/gtest.h>

#include "emulation/timevarying_emu.h"
#include "reference/timevarying/plume.h"

namespace voxref::conf {
namespace {

struct Fixture {
  ref::TimeSeries series = ref::driftingBlobs(16, 1);
  ref::TransferFunction tf = ref::transferFunction("gray");
  ref::TimeVaryingTextures tex = ref::encodeTimeVarying(series, tf, {1, ref::IndexEncoding::BlockRgba8});
  // Every voxel centre of the 16^3 volume.
  ref::PlaneFrame frame =
      ref::explicitFrame({0, 0, 0}, {1.0 / 16, 0, 0}, {0, 1.0 / 16, 0}, {0, 0, 1.0 / 16}, 16, 16, 16);
  emu::EmulatedDecode decoded =
      emu::emulateDecodePlanes(tex, ref::DecoderVariant::TexelFetch, 0, frame, *emu::findProfile("llvmpipe"));
};

FetchCounts classify(const Fixture& f, const ref::PlaneFrame& frame, const emu::EmulatedDecode& d) {
  return classifyFetches(f.tex, f.series, f.tf, 0, frame, emu::fetchesOf(d), d.colours.colours);
}

TEST(ClassifyFetches, RightFetchesAreRight) {
  Fixture f;
  const FetchCounts c = classify(f, f.frame, f.decoded);
  EXPECT_EQ(c.samples, 16u * 16 * 16);
  EXPECT_EQ(c.right, c.samples);
  EXPECT_EQ(c.wrong(), 0u);
  EXPECT_EQ(c.wrongColour, 0u);
}

TEST(ClassifyFetches, AnotherVoxelOrBlockIsCountedAndPlaced) {
  Fixture f;
  std::size_t refined = 0;
  while (!f.decoded.samples[refined].refined) ++refined;
  auto voxel = f.decoded, block = f.decoded;
  voxel.samples[refined].refinementTexel[0] ^= 1;  // a neighbour inside the same 8-voxel block
  block.samples[refined].refinementTexel[0] += 8;  // the same position in the next block slot
  const FetchCounts v = classify(f, f.frame, voxel);
  const FetchCounts b = classify(f, f.frame, block);
  EXPECT_EQ(v.wrongVoxel, 1u);
  EXPECT_EQ(v.wrongBlock, 0u);
  EXPECT_EQ(b.wrongBlock, 1u);
  EXPECT_EQ(v.inside + v.onVoxelFace + v.onBlockFace + v.atCoordinateOne, 1u);  // voxel centres are inside
  EXPECT_EQ(v.inside, 1u);
  ASSERT_EQ(v.examples.size(), 1u);
  EXPECT_EQ(v.examples[0]["kind"], "wrong_voxel");
}

TEST(ClassifyFetches, PlacesAtCoordinateOne) {
  Fixture f;
  const ref::PlaneFrame one =
      ref::explicitFrame({1.0 - 1.0 / 32, 0, 0}, {1.0 / 16, 0, 0}, {0, 1.0 / 16, 0}, {0, 0, 1.0 / 16}, 1, 16, 16);
  auto decoded =
      emu::emulateDecodePlanes(f.tex, ref::DecoderVariant::TexelFetch, 0, one, *emu::findProfile("llvmpipe"));
  EXPECT_EQ(classify(f, one, decoded).wrong(), 0u);  // texel_fetch clamps the cell
  decoded.samples[0].indexTexel[0] += 1;
  const FetchCounts c = classify(f, one, decoded);
  EXPECT_EQ(c.atCoordinateOne, 1u);
  EXPECT_EQ(c.wrongBlock, 1u);
}

TEST(FetchedColours, ExplainTheEmulationsColoursAndFlagAnotherOne) {
  Fixture f;
  const std::vector<ref::TexelFetch> fetches = emu::fetchesOf(f.decoded);
  const std::vector<ref::Rgba8> fetched = coloursOfFetches(f.tex, fetches);
  EXPECT_EQ(unexplainedColours(fetched, fetches, f.decoded.colours.colours), 0u);  // texel_fetch returns the texel
  std::vector<ref::Rgba8> other = f.decoded.colours.colours;
  other[5][1] ^= 1;
  EXPECT_EQ(unexplainedColours(fetched, fetches, other), 1u);
}

TEST(DifferingFetches, CountsEveryKindOfDifferenceOnce) {
  Fixture f;
  const std::vector<ref::TexelFetch> a = emu::fetchesOf(f.decoded);
  std::vector<ref::TexelFetch> b = a;
  EXPECT_EQ(differingFetches(a, b), 0u);
  std::size_t refined = 0;
  while (refined < a.size() && !a[refined].refined) ++refined;
  ASSERT_LT(refined, a.size());
  b[refined].refinementTexel[2] += 1;
  EXPECT_EQ(differingFetches(a, b), 1u);
  b[refined].refinementTexel = a[refined].refinementTexel;
  b[refined].refined = false;  // no refinement fetch: differs, whatever its refinement texel
  EXPECT_EQ(differingFetches(a, b), 1u);
  b[refined].refined = true;
  b[0].indexTexel[0] += 1;
  b[1].discarded = true;
  EXPECT_EQ(differingFetches(a, b), 2u);
  std::vector<ref::TexelFetch> c = a;
  c[refined].refined = false, c[refined].refinementTexel[0] += 3;
  std::vector<ref::TexelFetch> d = c;
  d[refined].refinementTexel[0] += 1;  // neither fetched the refinement texture: no difference
  EXPECT_EQ(differingFetches(c, d), 0u);
}

}  // namespace
}  // namespace voxref::conf
