#include "reference/timevarying/address_textures.h"

#include <bit>

#include <gtest/gtest.h>

#include "reference/timevarying/plume.h"

namespace voxref::ref {
namespace {

TEST(AddressCode, NamesEveryTexelUpTo1024AndIsNeverAFlag) {
  for (int i : {0, 1, 255, 256, 511, 767, 1023})
    for (int j : {0, 300, 1023})
      for (int k : {0, 7, 600, 1023}) {
        const Rgba8 c = addressCode({i, j, k});
        EXPECT_GE(c[3], 64);
        EXPECT_LE(c[3], 127);
        const auto t = texelOfAddressCode(c);
        ASSERT_TRUE(t.has_value());
        EXPECT_EQ(*t, (std::array<int, 3>{i, j, k}));
      }
  EXPECT_EQ(texelOfAddressCode({0, 0, 0, 0}), kNoTexel);  // a fetch outside the texture that returned zero
  EXPECT_FALSE(texelOfAddressCode({1, 2, 3, 0}).has_value());
  EXPECT_FALSE(texelOfAddressCode({1, 2, 3, 63}).has_value());
  EXPECT_FALSE(texelOfAddressCode({1, 2, 3, 128}).has_value());
  EXPECT_FALSE(texelOfAddressCode({1, 2, 3, 255}).has_value());
}

TEST(AddressTextures, HoldEachTexelsCodeInTheIndexsEncodingAndNoFlag) {
  const TimeSeries series = driftingBlobs(16, 3);
  const TransferFunction tf = transferFunction("gray");
  for (IndexEncoding e : {IndexEncoding::NormalizedRgba8, IndexEncoding::NormalizedRgba16,
                          IndexEncoding::NormalizedFloat, IndexEncoding::BlockRgba8}) {
    const TimeVaryingTextures tex = encodeTimeVarying(series, tf, {2, e});
    const IndexTexture a = addressIndexTexture(tex.index);
    ASSERT_EQ(a.dims, tex.index.dims);
    ASSERT_EQ(a.encoding, e);
    ASSERT_EQ(a.texels.size(), tex.index.texels.size());
    std::size_t n = 0;
    for (int k = 0; k < a.dims[2]; ++k)
      for (int j = 0; j < a.dims[1]; ++j)
        for (int i = 0; i < a.dims[0]; ++i, ++n) {
          EXPECT_FALSE(isRefinementFlag(e, &a.texels[4 * n]));
          // Read back as a decoder returns a homogeneous cell's colour: the code, whatever the encoding.
          EXPECT_EQ(colourOfIndexTexel(e, &a.texels[4 * n]), addressCode({i, j, k}));
        }
    const RefinementTexture r = addressRefinementTexture(tex.refinement);
    ASSERT_EQ(r.dims, tex.refinement.dims);
    const std::size_t last = r.texels.size() / 4 - 1;
    EXPECT_EQ((Rgba8{r.texels[4 * last], r.texels[4 * last + 1], r.texels[4 * last + 2], r.texels[4 * last + 3]}),
              addressCode({r.dims[0] - 1, r.dims[1] - 1, r.dims[2] - 1}));
  }
}

TEST(AddressTextures, RefuseExtentsTheyCannotName) {
  const IndexTexture wide{IndexEncoding::NormalizedRgba8, {1025, 1, 1}, std::vector<std::uint32_t>(4 * 1025)};
  try {
    (void)addressIndexTexture(wide);
    FAIL() << "a 1025-texel axis was addressed";
  } catch (const std::length_error& e) {
    EXPECT_NE(std::string(e.what()).find("index texture is 1025x1x1"), std::string::npos) << e.what();
  }
}

// Passes built by hand from the exact decoder's addresses (what a decoder that fetches right would
// write) decode back to those addresses; a colour that is no code is counted, never guessed.
TEST(FetchesFromAddressPasses, RecoverTheFetchedTexelsAndCountUnreadableOnes) {
  const TimeSeries series = driftingBlobs(16, 2);
  const TransferFunction tf = transferFunction("gray");
  const TimeVaryingTextures tex = encodeTimeVarying(series, tf, {2, IndexEncoding::BlockRgba8});
  const PlaneFrame frame = explicitFrame({0, 0, 0}, {1.0 / 16, 0, 0}, {0, 1.0 / 16, 0}, {0, 0, 1.0 / 16}, 16, 16, 16);
  RgbaStack indexPass{16, 16, 16, {}}, refinementPass{16, 16, 16, {}};
  std::vector<VoxelAddress> want;
  for (int z = 0; z < 16; ++z)
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) {
        want.push_back(addressOfVoxel(tex, 1, x, y, z));
        indexPass.colours.push_back(addressCode(want.back().indexTexel));
        refinementPass.colours.push_back(want.back().refined ? addressCode(want.back().refinementTexel)
                                                             : decodeVoxel(tex, 1, x, y, z));
      }
  MeasuredFetches m = fetchesFromAddressPasses(tex, frame, indexPass, refinementPass);
  ASSERT_EQ(m.fetches.size(), want.size());
  EXPECT_EQ(m.unreadable, 0u);
  std::size_t refined = 0;
  for (std::size_t n = 0; n < want.size(); ++n) {
    EXPECT_FALSE(m.fetches[n].discarded);
    EXPECT_EQ(m.fetches[n].indexTexel, want[n].indexTexel);
    ASSERT_EQ(m.fetches[n].refined, want[n].refined);
    if (want[n].refined) {
      EXPECT_EQ(m.fetches[n].refinementTexel, want[n].refinementTexel);
      ++refined;
    }
  }
  ASSERT_GT(refined, 0u);
  indexPass.colours[3] = {9, 9, 9, 200};
  m = fetchesFromAddressPasses(tex, frame, indexPass, refinementPass);
  EXPECT_EQ(m.unreadable, 1u);
  EXPECT_THROW((void)fetchesFromAddressPasses(tex, frame, RgbaStack{1, 1, 1, {{0, 0, 0, 0}}}, refinementPass),
               std::invalid_argument);
}

TEST(FetchesFromAddressPasses, SamplesOutsideTheUnitCubeAreDiscarded) {
  const TimeSeries series = driftingBlobs(16, 1);
  const TimeVaryingTextures tex = encodeTimeVarying(series, transferFunction("gray"), {2, IndexEncoding::BlockRgba8});
  const PlaneFrame frame = explicitFrame({-0.5, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 0.5}, 2, 1, 1);
  const RgbaStack zero{2, 1, 1, {{0, 0, 0, 0}, {0, 0, 0, 0}}};
  const MeasuredFetches m = fetchesFromAddressPasses(tex, frame, zero, zero);
  EXPECT_TRUE(m.fetches[0].discarded);  // x = -0.25
  EXPECT_FALSE(m.fetches[1].discarded);
  EXPECT_EQ(m.fetches[1].indexTexel, kNoTexel);  // zero: a fetch that read no texel
  EXPECT_FALSE(m.fetches[1].refined);
  EXPECT_EQ(colourOfFetch(tex, m.fetches[1]), (Rgba8{0, 0, 0, 0}));
  EXPECT_EQ(m.unreadable, 0u);
}

}  // namespace
}  // namespace voxref::ref
