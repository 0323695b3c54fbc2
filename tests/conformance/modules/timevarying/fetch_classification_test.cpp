#include "conformance/modules/timevarying/fetch_classification.h"

#include <gtest/gtest.h>

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

TEST(ClassifyFetches, RightFetchesAreRight) {
  Fixture f;
  const FetchCounts c = classifyFetches(f.tex, f.series, f.tf, 0, f.frame, f.decoded);
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
  const FetchCounts v = classifyFetches(f.tex, f.series, f.tf, 0, f.frame, voxel);
  const FetchCounts b = classifyFetches(f.tex, f.series, f.tf, 0, f.frame, block);
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
  EXPECT_EQ(classifyFetches(f.tex, f.series, f.tf, 0, one, decoded).wrong(), 0u);  // texel_fetch clamps the cell
  decoded.samples[0].indexTexel[0] += 1;
  const FetchCounts c = classifyFetches(f.tex, f.series, f.tf, 0, one, decoded);
  EXPECT_EQ(c.atCoordinateOne, 1u);
  EXPECT_EQ(c.wrongBlock, 1u);
}

}  // namespace
}  // namespace voxref::conf
