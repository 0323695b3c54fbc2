#include "reference/common/plane_frame.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

namespace voxref::ref {
namespace {

// Every sample coordinate and partial sum of the shader's expression survives float32 unchanged.
void expectFloat32Exact(const PlaneFrame& f) {
  for (int k = 0; k < f.planes; k += std::max(1, f.planes / 7))
    for (int j = 0; j < f.height; j += std::max(1, f.height / 5))
      for (int i = 0; i < f.width; ++i) {
        const glm::dvec3 o = f.planeOrigin(k), partial = o + (i + 0.5) * f.dx, p = f.sample(i, j, k);
        for (int a = 0; a < 3; ++a) {
          ASSERT_EQ(static_cast<double>(static_cast<float>(o[a])), o[a]);
          ASSERT_EQ(static_cast<double>(static_cast<float>(partial[a])), partial[a]);
          ASSERT_EQ(static_cast<double>(static_cast<float>(p[a])), p[a]);
          // float32 evaluation of ((o + fx*dx) + fy*dy), operation by operation:
          const float fx = static_cast<float>(i) + 0.5f, fy = static_cast<float>(j) + 0.5f;
          const float t1 = fx * static_cast<float>(f.dx[a]);
          const float t2 = static_cast<float>(o[a]) + t1;
          const float t3 = fy * static_cast<float>(f.dy[a]);
          ASSERT_EQ(static_cast<double>(t2 + t3), p[a]);
        }
      }
}

TEST(OrbitFrame, IsFloat32ExactForManyDirections) {
  for (double az : {0.0, 17.0, 30.0, 45.0, 90.0, 133.0, 271.0})
    for (double el : {-60.0, 0.0, 20.0, 45.0, 89.0}) {
      const PlaneFrame f = orbitFrame(az, el, 64, 48, 40);
      EXPECT_EQ(float32ExactnessViolation(f), "") << az << " " << el;
      expectFloat32Exact(f);
    }
  expectFloat32Exact(orbitFrame(30.0, 20.0, 200, 200, 128));
}

TEST(OrbitFrame, CoversTheUnitCube) {
  // The view box is centred on the cube and the corners of the cube project inside it.
  const PlaneFrame f = orbitFrame(37.0, 23.0, 32, 32, 32);
  const glm::dvec3 centre = f.origin + 0.5 * (32.0 * f.dx + 32.0 * f.dy + 32.0 * f.dz);
  EXPECT_NEAR(centre.x, 0.5, 1e-5);
  EXPECT_NEAR(centre.y, 0.5, 1e-5);
  EXPECT_NEAR(centre.z, 0.5, 1e-5);
  // Snapping moves each component by at most 2^-22, so a dot product of orthogonal vectors moves
  // by at most (|a|_1 + |b|_1) 2^-22 + 3 * 2^-44.
  auto bound = [](glm::dvec3 a, glm::dvec3 b) {
    const double l1 =
        std::fabs(a.x) + std::fabs(a.y) + std::fabs(a.z) + std::fabs(b.x) + std::fabs(b.y) + std::fabs(b.z);
    return l1 * std::ldexp(1.0, -22) + 3 * std::ldexp(1.0, -44);
  };
  EXPECT_NEAR(glm::dot(f.dx, f.dy), 0.0, bound(f.dx, f.dy));
  EXPECT_NEAR(glm::dot(f.dx, f.dz), 0.0, bound(f.dx, f.dz));
}

TEST(ExplicitFrame, RejectsOffLatticeAndHugeFrames) {
  EXPECT_THROW(explicitFrame({0.1, 0, 0}, {1.0 / 16, 0, 0}, {0, 1.0 / 16, 0}, {0, 0, 1.0 / 16}, 16, 16, 16),
               std::invalid_argument);  // 0.1 is not on the 2^-22 lattice
  EXPECT_THROW(explicitFrame({0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 0.5}, 16, 16, 16),
               std::invalid_argument);  // reaches magnitude 8
  EXPECT_THROW(explicitFrame({0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 0.5}, 0, 16, 16), std::invalid_argument);
  const PlaneFrame f = explicitFrame({-1.0 / 32, -1.0 / 32, -1.0 / 32}, {1.0 / 16, 0, 0}, {0, 1.0 / 16, 0},
                                     {0, 0, 1.0 / 16}, 17, 17, 17);
  EXPECT_EQ(f.sample(0, 0, 0), glm::dvec3(0.0));     // on the corner node
  EXPECT_EQ(f.sample(16, 16, 16), glm::dvec3(1.0));  // coordinate 1.0 exactly
}

TEST(ExplicitFrame, OffTheLatticeButExactSampleBySample) {
  const double u = std::ldexp(1.0, -24);
  // dx = 2^-23 is off the 2^-21 lattice; every sample 0.75 +- 2^-24 is a float32.
  const PlaneFrame f =
      explicitFrame({0.75 - 2 * u, 0.5, 0.5}, {2 * u, 0, 0}, {0, 1.0 / 16, 0}, {0, 0, 1.0 / 16}, 2, 1, 1);
  EXPECT_EQ(f.sample(0, 0, 0).x, 0.75 - u);
  EXPECT_EQ(f.sample(1, 0, 0).x, 0.75 + u);
  // Off the lattice and not exact: 0.5 + 2^-26 is not a float32.
  EXPECT_THROW(
      explicitFrame({0.5, 0.5, 0.5}, {std::ldexp(1.0, -25), 0, 0}, {0, 1.0 / 16, 0}, {0, 0, 1.0 / 16}, 2, 1, 1),
      std::invalid_argument);
}

TEST(StraddlingFrame, OneUlpEitherSideOfEveryFace) {
  const double u = std::ldexp(1.0, -24);
  const PlaneFrame f = straddlingFrame(1.0 / 32, 1.0 / 16, 16, {0, 1.0 / 16, 0.0}, 17, {0, 0, 0.53125});
  ASSERT_EQ(f.width, 2);
  ASSERT_EQ(f.height, 16);
  ASSERT_EQ(f.planes, 17);
  for (int k = 0; k < f.planes; ++k)
    for (int m = 0; m < f.height; ++m) {
      const double face = 1.0 / 32 + m / 16.0;
      const glm::dvec3 below = f.sample(0, m, k), above = f.sample(1, m, k);
      EXPECT_EQ(below.x, face - u);
      EXPECT_EQ(above.x, face + u);
      EXPECT_EQ(below.y, k / 16.0);
      EXPECT_EQ(below.z, 0.53125);
      if (face > 0.5) {  // one float32 ulp: the neighbours of the face itself
        EXPECT_EQ(static_cast<double>(std::nextafter(static_cast<float>(face), 0.0f)), below.x);
        EXPECT_EQ(static_cast<double>(std::nextafter(static_cast<float>(face), 2.0f)), above.x);
      }
    }
}

}  // namespace
}  // namespace voxref::ref
