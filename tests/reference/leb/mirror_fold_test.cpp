// Mirror folds (reference/leb/mirror_fold.h): the geometry against its definition counted point by
// point, the search on volumes built to be mirror images of themselves (and on ones that are not),
// and fold then unfold giving back every sample.
#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "reference/leb/gradients.h"
#include "reference/leb/mirror_fold.h"
#include "tests/reference/leb/leb_test_volumes.h"
#include "tests/reference/leb/mirror_test_volumes.h"

namespace voxref::ref {
namespace {

using test_support::mirrored;
using test_support::mirroredGradients;
using test_support::noise;

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
    EXPECT_EQ(findLebMirrorPlanes(v.data().data(), nullptr, b.dims), b.planes) << dimsText(b.dims);
  }
  // Noise has no plane; neither has a volume too thin to fold.
  const Volume<std::uint16_t> n = noise({30, 30, 30}, 8, 5);
  EXPECT_FALSE(findLebMirrorPlanes(n.data().data(), nullptr, n.dims()).any());
  const Volume<std::uint16_t> thin = mirrored(noise({3, 3, 3}, 8, 5), {{2, 2, 2}});
  EXPECT_FALSE(findLebMirrorPlanes(thin.data().data(), nullptr, thin.dims()).any());
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
  EXPECT_EQ(findLebMirrorPlanes(near.data().data(), nullptr, d), planes);
  Volume<std::uint16_t> far = near;
  for (int i = 0; i < 60; ++i) {  // 80 in 32,000: one in 400
    auto& s = far.at(static_cast<int>(rng() % 40), 20 + static_cast<int>(rng() % 20), static_cast<int>(rng() % 40));
    s = static_cast<std::uint16_t>((s + 1) & 255);
  }
  EXPECT_FALSE(findLebMirrorPlanes(far.data().data(), nullptr, d).any());
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
        foldLebVolume(v.data().data(), nullptr, c.dims, c.planes, c.bits, buffer.data(), nullptr);
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
    unfoldLebVolume(buffer.data(), nullptr, c.dims, c.planes, c.bits, exceptions,
                    [&](double d) { progress.push_back(d); });
    EXPECT_EQ(buffer, v.data()) << dimsText(c.dims);
    ASSERT_FALSE(progress.empty());
    EXPECT_EQ(progress.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  }
}

// Random gradients (3 int8 a point), made to mirror with `planes`.
std::vector<std::int8_t> randomMirroredGradients(const Dims3& d, const LebMirrorPlanes& planes, unsigned seed) {
  std::vector<std::int8_t> g(3 * sampleCount(d));
  std::mt19937 rng(seed);
  for (std::int8_t& c : g) c = static_cast<std::int8_t>(static_cast<int>(rng() % 256) - 128);
  return mirroredGradients(std::move(g), d, planes);
}

TEST(MirrorFold, GradientsFoldWithTheSignOfTheirMirrorAndUnfoldToEveryComponent) {
  EXPECT_EQ(lebMirrorComponent(5, true, 0), -5);
  EXPECT_EQ(lebMirrorComponent(-128, true, 0), -128);
  EXPECT_EQ(lebMirrorComponent(127, false, 1), -128);
  EXPECT_EQ(lebMirrorComponentResidual(-7, 7, true), 0);
  EXPECT_EQ(lebMirrorComponentResidual(3, 7, true), 10);
  const Dims3 d{20, 24, 18};
  const LebMirrorPlanes planes{{25, 23, 14}};
  const Volume<std::uint16_t> v = mirrored(noise(d, 8, 3), planes);
  std::vector<std::int8_t> g = randomMirroredGradients(d, planes, 4);
  std::vector<std::uint8_t> samples(v.data().begin(), v.data().end());
  std::vector<std::uint8_t> folded(samples.size());
  std::vector<std::int8_t> foldedGradients(g.size());
  EXPECT_TRUE(foldLebVolume(samples.data(), g.data(), d, planes, folded.data(), foldedGradients.data()).empty());
  // Three points off their mirrored gradient (one also off its sample), at mirrored points.
  const std::size_t moved[3] = {v.index(19, 0, 0), v.index(0, 20, 17), v.index(19, 23, 17)};
  g[3 * moved[0] + 0] = static_cast<std::int8_t>(g[3 * moved[0]] + 1);
  g[3 * moved[1] + 2] = static_cast<std::int8_t>(g[3 * moved[1] + 2] - 100);
  samples[moved[2]] = static_cast<std::uint8_t>(samples[moved[2]] + 9);
  g[3 * moved[2] + 1] = static_cast<std::int8_t>(g[3 * moved[2] + 1] ^ 64);
  const std::vector<LebMirrorException> exceptions =
      foldLebVolume(samples.data(), g.data(), d, planes, folded.data(), foldedGradients.data());
  ASSERT_EQ(exceptions.size(), 3u);
  EXPECT_EQ(exceptions[0], (LebMirrorException{moved[0], 0, {1, 0, 0}}));
  EXPECT_EQ(exceptions[1], (LebMirrorException{moved[1], 0, {0, 0, 156}}));
  EXPECT_EQ(exceptions[2].residual, 9u);
  // The folded gradients are the kept points', in order; unfolded in place they are every point's.
  const Dims3 f = lebFoldedDims(d, planes);
  std::size_t at = 0;
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x)
        if (!lebMirroredCoordinate(x, planes.sum[0]) && !lebMirroredCoordinate(y, planes.sum[1]) &&
            !lebMirroredCoordinate(z, planes.sum[2])) {
          ASSERT_TRUE(std::equal(g.begin() + 3 * v.index(x, y, z), g.begin() + 3 * v.index(x, y, z) + 3,
                                 foldedGradients.begin() + 3 * at));
          ++at;
        }
  ASSERT_EQ(at, sampleCount(f));
  std::vector<std::uint8_t> back = folded;
  std::vector<std::int8_t> backGradients = foldedGradients;
  back.resize(samples.size());
  backGradients.resize(g.size());
  unfoldLebVolume(back.data(), backGradients.data(), d, planes, exceptions);
  EXPECT_EQ(back, samples);
  EXPECT_EQ(backGradients, g);
}

TEST(MirrorFold, CentralDifferencesOfAVolumeMirroredAcrossItsCentresMirrorExactly) {
  // Across the central plane of an axis (s = n - 1) a face pairs with a face, and each point's
  // difference quotient with its image's negated (gradients.h: the one-sided ones too); normalising
  // and rounding half away from zero keep the sign's symmetry. So no gradient differs.
  const Dims3 d{18, 13, 10};
  const LebMirrorPlanes centres{{17, 12, 9}};
  const Volume<std::uint16_t> v = mirrored(noise(d, 8, 6), centres);
  const std::vector<std::int8_t> g = quantizedGradients(v);
  std::vector<std::uint16_t> folded(v.data().size());
  std::vector<std::int8_t> foldedGradients(g.size());
  EXPECT_TRUE(foldLebVolume(v.data().data(), g.data(), d, centres, 8, folded.data(), foldedGradients.data()).empty());
  EXPECT_EQ(findLebMirrorPlanes(v.data().data(), g.data(), d), centres);
  // Off centre (s = n - 3 on x) the points of the slice x = s have a central difference and their
  // images on the face x = 0 a one-sided one: most of that slice differs (130 of its 130 points
  // here, 1 in 8 of the 1,040 mirrored points), more than one in 16: the fold is refused, and the
  // search drops the plane.
  const LebMirrorPlanes off{{15, kNoLebMirror, kNoLebMirror}};
  const Volume<std::uint16_t> w = mirrored(noise(d, 8, 6), off);
  const std::vector<std::int8_t> wg = quantizedGradients(w);
  EXPECT_EQ(findLebMirrorPlanes(w.data().data(), nullptr, d), off);
  EXPECT_FALSE(findLebMirrorPlanes(w.data().data(), wg.data(), d).any());
  try {
    foldLebVolume(w.data().data(), wg.data(), d, off, 8, folded.data(), foldedGradients.data());
    FAIL() << "a fold with a slice of differing gradients";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("in their sample or gradient, more than the 65 (one in 16 mirrored points)"),
              std::string::npos)
        << e.what();
  }
}

TEST(MirrorFold, AFoldWithTooManyExceptionsIsRefused) {
  const Volume<std::uint16_t> v = noise({16, 16, 16}, 8, 1);
  std::vector<std::uint8_t> in(v.data().begin(), v.data().end()), out(in.size());
  try {
    foldLebVolume(in.data(), nullptr, v.dims(), {{15, kNoLebMirror, kNoLebMirror}}, out.data(), nullptr);
    FAIL() << "noise folded";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("more than the 8 (one in 256 mirrored points)"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace voxref::ref
