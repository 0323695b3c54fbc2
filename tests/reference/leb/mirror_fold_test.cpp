// Mirror folds (reference/leb/mirror_fold.h): the geometry against its definition counted point by
// point, the search on volumes built to be mirror images of themselves (and on ones that are not),
// and fold then unfold giving back every sample.
#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "reference/leb/mirror_fold.h"
#include "tests/reference/leb/leb_test_volumes.h"

namespace voxref::ref {
namespace {

using test_support::noise;

// `v` made a mirror image of itself: each point whose coordinates are mirrored takes its image's
// sample (by the definition in mirror_fold.h, written out here), so the planes hold exactly.
Volume<std::uint16_t> mirrored(Volume<std::uint16_t> v, const LebMirrorPlanes& planes) {
  const Dims3 d = v.dims();
  auto image = [&](int c, int a) {
    const std::int64_t s = planes.sum[a];
    return s >= 0 && 2 * std::int64_t{c} > s && c <= s ? static_cast<int>(s - c) : c;
  };
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x) v.at(x, y, z) = v.at(image(x, 0), image(y, 1), image(z, 2));
  return v;
}

TEST(MirrorFold, FoldedCoordinatesAreTheRanksOfTheImagesAmongTheKeptCoordinates) {
  for (int n = 1; n <= 12; ++n)
    for (std::int64_t s = 1; s <= 2 * n - 3; ++s) {
      std::vector<int> kept;  // by the definition: c is mirrored when s/2 < c <= s
      for (int c = 0; c < n; ++c)
        if (!(2 * c > s && c <= s)) kept.push_back(c);
      ASSERT_EQ(lebFoldedExtent(n, s), static_cast<int>(kept.size())) << "n " << n << " s " << s;
      for (int c = 0; c < n; ++c) {
        const int image = 2 * c > s && c <= s ? static_cast<int>(s - c) : c;
        const auto rank = std::find(kept.begin(), kept.end(), image) - kept.begin();
        ASSERT_LT(rank, static_cast<std::ptrdiff_t>(kept.size())) << "the image of " << c << " is not kept";
        EXPECT_EQ(lebFoldedCoordinate(c, s), rank) << "n " << n << " s " << s << " c " << c;
        EXPECT_LE(lebFoldedCoordinate(c, s), c);  // what the in-place unfold relies on
      }
    }
  EXPECT_EQ(lebFoldedExtent(9, kNoLebMirror), 9);
  EXPECT_EQ(lebFoldedCoordinate(7, kNoLebMirror), 7);
  EXPECT_EQ(lebFoldedDims({128, 128, 128}, {{124, 126, 126}}), (Dims3{66, 65, 65}));
}

TEST(MirrorFold, SumsThatMirrorNothingAreRefused) {
  EXPECT_FALSE(lebMirrorSumValid(0, 10));
  EXPECT_TRUE(lebMirrorSumValid(17, 10));
  EXPECT_FALSE(lebMirrorSumValid(18, 10));
  try {
    requireLebMirrorPlanes({10, 10, 10}, {{kNoLebMirror, 18, kNoLebMirror}});
    FAIL() << "a sum of 18 for an extent of 10 mirrors nothing";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "mirror sum on y: expected 1..17 for an extent of 10, got 18");
  }
}

TEST(MirrorFold, TheSearchFindsThePlanesAVolumeWasBuiltWith) {
  struct Built {
    Dims3 dims;
    LebMirrorPlanes planes;
  };
  const Built cases[] = {
      {{32, 20, 16}, {{31, kNoLebMirror, kNoLebMirror}}},  // the central plane of an even extent
      {{33, 20, 16}, {{32, kNoLebMirror, kNoLebMirror}}},  // of an odd one: x = 16 is its own image
      {{20, 24, 18}, {{25, 23, 14}}},                      // off centre, above the extent, below it
      {{41, 41, 41}, {{38, kNoLebMirror, 40}}},
  };
  for (const Built& b : cases) {
    const Volume<std::uint16_t> v = mirrored(noise(b.dims, 8, 11), b.planes);
    EXPECT_EQ(findLebMirrorPlanes(v.data().data(), b.dims), b.planes) << dimsText(b.dims);
  }
  // Noise has no plane; neither has a volume too thin to fold.
  const Volume<std::uint16_t> n = noise({30, 30, 30}, 8, 5);
  EXPECT_FALSE(findLebMirrorPlanes(n.data().data(), n.dims()).any());
  const Volume<std::uint16_t> thin = mirrored(noise({3, 3, 3}, 8, 5), {{2, 2, 2}});
  EXPECT_FALSE(findLebMirrorPlanes(thin.data().data(), thin.dims()).any());
}

TEST(MirrorFold, TheSearchKeepsANearMirrorAndDropsOneThatDiffersTooOften) {
  const Dims3 d{40, 40, 40};
  const LebMirrorPlanes planes{{kNoLebMirror, 39, kNoLebMirror}};
  Volume<std::uint16_t> near = mirrored(noise(d, 8, 2), planes);
  // 20 of the 32,000 mirrored points differ (one in 1,600): within one in 1,024.
  std::mt19937 rng(9);
  for (int i = 0; i < 20; ++i) {
    auto& s = near.at(static_cast<int>(rng() % 40), 20 + static_cast<int>(rng() % 20), static_cast<int>(rng() % 40));
    s = static_cast<std::uint16_t>((s + 1) & 255);
  }
  EXPECT_EQ(findLebMirrorPlanes(near.data().data(), d), planes);
  Volume<std::uint16_t> far = near;
  for (int i = 0; i < 60; ++i) {  // 80 in 32,000: one in 400
    auto& s = far.at(static_cast<int>(rng() % 40), 20 + static_cast<int>(rng() % 20), static_cast<int>(rng() % 40));
    s = static_cast<std::uint16_t>((s + 1) & 255);
  }
  EXPECT_FALSE(findLebMirrorPlanes(far.data().data(), d).any());
}

TEST(MirrorFold, FoldThenUnfoldGivesBackEverySample) {
  struct Case {
    Dims3 dims;
    LebMirrorPlanes planes;
    int bits;
  };
  const Case cases[] = {{{20, 24, 18}, {{25, 23, 14}}, 8},
                        {{33, 15, 9}, {{32, kNoLebMirror, 7}}, 16},
                        {{2, 2, 9}, {{1, 1, 15}}, 8},
                        {{64, 1, 1}, {{63, kNoLebMirror, kNoLebMirror}}, 16}};
  for (const Case& c : cases) {
    Volume<std::uint16_t> v = mirrored(noise(c.dims, c.bits, 3), c.planes);
    // A few exceptions: mirrored points off their image by +1, by -1, and by the widest residual.
    const std::uint32_t top = (1u << c.bits) - 1;
    std::vector<std::size_t> changed;
    // As many as the format allows, up to three (none where fewer than 256 points are mirrored).
    const auto most = static_cast<std::ptrdiff_t>(
        std::min<std::uint64_t>(3, lebMirroredPoints(c.dims, c.planes) / kLebMirrorExceptionShare));
    for (std::ptrdiff_t j = static_cast<std::ptrdiff_t>(v.data().size()) - 1, k = 0; k < most && j >= 0; j -= 7)
      if (const auto i = static_cast<std::size_t>(j);
          lebMirroredCoordinate(static_cast<int>(i % static_cast<std::size_t>(c.dims[0])), c.planes.sum[0])) {
        v.data()[i] = static_cast<std::uint16_t>((v.data()[i] + (k == 0 ? 1 : k == 1 ? top : top / 2 + 1)) & top);
        changed.push_back(i);
        ++k;
      }
    const Dims3 f = lebFoldedDims(c.dims, c.planes);
    std::vector<std::uint16_t> buffer(v.data().size());
    const std::vector<LebMirrorException> exceptions =
        foldLebVolume(v.data().data(), c.dims, c.planes, c.bits, buffer.data());
    ASSERT_EQ(exceptions.size(), changed.size()) << dimsText(c.dims);
    for (const LebMirrorException& e : exceptions)
      EXPECT_NE(std::find(changed.begin(), changed.end(), e.index), changed.end());
    // The folded volume's samples are the kept points', in order.
    for (int z = 0; z < f[2]; ++z)
      for (int y = 0; y < f[1]; ++y)
        for (int x = 0; x < f[0]; ++x) {
          auto keptAt = [&](int fc, int a) {  // the kept coordinate at folded place fc
            for (int q = 0; q < c.dims[a]; ++q)
              if (!lebMirroredCoordinate(q, c.planes.sum[a]) && lebFoldedCoordinate(q, c.planes.sum[a]) == fc) return q;
            return -1;
          };
          ASSERT_EQ(buffer[x + f[0] * (y + f[1] * z)], v.at(keptAt(x, 0), keptAt(y, 1), keptAt(z, 2)));
        }
    std::vector<double> progress;
    unfoldLebVolume(buffer.data(), c.dims, c.planes, c.bits, exceptions, [&](double d) { progress.push_back(d); });
    EXPECT_EQ(buffer, v.data()) << dimsText(c.dims);
    ASSERT_FALSE(progress.empty());
    EXPECT_EQ(progress.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  }
}

TEST(MirrorFold, AFoldWithTooManyExceptionsIsRefused) {
  const Volume<std::uint16_t> v = noise({16, 16, 16}, 8, 1);
  std::vector<std::uint8_t> in(v.data().begin(), v.data().end()), out(in.size());
  try {
    foldLebVolume(in.data(), v.dims(), {{15, kNoLebMirror, kNoLebMirror}}, out.data());
    FAIL() << "noise folded";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("more than the 8 (one in 256 mirrored points)"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace voxref::ref
