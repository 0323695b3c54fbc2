// Marching tetrahedra on fully refined LEB meshes: closedness, orientation, the rule for values
// equal to the isovalue, and the hard cases of the isosurface system (issue 5).
#include "reference/iso/marching_tetrahedra.h"

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "reference/iso/extraction.h"
#include "tests/reference/iso/iso_mesh_checks.h"
#include "tests/reference/iso/iso_test_fields.h"
#include "tests/reference/leb/grid_points.h"

namespace voxref::ref {
namespace {

using test_support::ballVolume;
using test_support::denseField;
using test_support::fullyRefined;
using test_support::hasRepeatedIndex;
using test_support::unmatchedDirectedEdges;
using test_support::volumeOf;

IsoMesh extractFull(const Volume<std::uint16_t>& v, double iso) {
  DenseGridField field = denseField(v);
  return extractIsosurface(fullyRefined(field.grid()), field, nullptr, iso);
}

TEST(MarchingTetrahedra, ABallIsClosedAndFacesOutwards) {
  const glm::dvec3 c(8.3, 7.9, 8.1);
  const IsoMesh m = extractFull(ballVolume({17, 17, 17}, c.x, c.y, c.z), 500.0);  // radius 5
  ASSERT_GT(m.triangleCount(), 100u);
  EXPECT_EQ(unmatchedDirectedEdges(m), 0u);
  EXPECT_FALSE(hasRepeatedIndex(m));
  ASSERT_EQ(m.triangleDiamond.size(), m.triangleCount());
  for (const glm::vec3& p : m.positions) EXPECT_NEAR(glm::length(glm::dvec3(p) - c), 5.0, 0.1);
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const glm::dvec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                     d = m.positions[m.indices[t + 2]];
    const glm::dvec3 n = glm::cross(b - a, d - a);
    EXPECT_GT(glm::dot(n, (a + b + d) / 3.0 - c), 0.0) << "triangle " << t / 3 << " faces inwards";
  }
  for (std::size_t v = 0; v < m.normals.size(); ++v)
    EXPECT_GT(glm::dot(glm::dvec3(m.normals[v]), glm::dvec3(m.positions[v]) - c),
              0.9 * glm::length(glm::dvec3(m.positions[v]) - c));
}

TEST(MarchingTetrahedra, IsovalueEqualToManyVertexValuesStaysClosed) {
  // Values in steps of 100, so hundreds of grid points equal the isovalue 500 exactly.
  const Volume<std::uint16_t> v = volumeOf({17, 17, 17}, [](int x, int y, int z) {
    return 1000.0 -
           100.0 * std::round(std::sqrt((x - 8.0) * (x - 8.0) + (y - 8.0) * (y - 8.0) + (z - 8.0) * (z - 8.0)));
  });
  int equal = 0;
  for (std::uint16_t s : v.data()) equal += s == 500;
  ASSERT_GT(equal, 50);
  const IsoMesh m = extractFull(v, 500.0);
  ASSERT_GT(m.triangleCount(), 0u);
  EXPECT_EQ(unmatchedDirectedEdges(m), 0u);
  EXPECT_FALSE(hasRepeatedIndex(m));
  // The rule: a vertex equal to the isovalue is inside, so the surface passes through it (the
  // crossing of an edge towards it is the vertex itself) and never through a point beyond it.
  int onGridPoints = 0;
  for (const glm::vec3& p : m.positions) {
    const bool integral = p.x == std::floor(p.x) && p.y == std::floor(p.y) && p.z == std::floor(p.z);
    if (integral) {
      ++onGridPoints;
      EXPECT_EQ(v.at(static_cast<int>(p.x), static_cast<int>(p.y), static_cast<int>(p.z)), 500);
    }
  }
  EXPECT_GT(onGridPoints, 0);
}

TEST(MarchingTetrahedra, AFlatRegionAtTheIsovalueIsInsideAndClosed) {
  const Volume<std::uint16_t> v = volumeOf({17, 17, 17}, [](int x, int y, int z) {
    const double r = std::sqrt((x - 8.0) * (x - 8.0) + (y - 8.0) * (y - 8.0) + (z - 8.0) * (z - 8.0));
    return r <= 3.5 ? 500.0 : 0.0;
  });
  const IsoMesh m = extractFull(v, 500.0);
  ASSERT_GT(m.triangleCount(), 0u);
  EXPECT_EQ(unmatchedDirectedEdges(m), 0u);
  EXPECT_FALSE(hasRepeatedIndex(m));
  // Every vertex is a grid point of the plateau (t = 1 on every crossing edge).
  for (const glm::vec3& p : m.positions)
    EXPECT_EQ(v.at(static_cast<int>(p.x), static_cast<int>(p.y), static_cast<int>(p.z)), 500);
}

TEST(MarchingTetrahedra, ASingleVoxelFeatureGivesASmallClosedSurface) {
  Volume<std::uint16_t> v({17, 17, 17}, 0);
  v.at(9, 6, 11) = 1000;
  const IsoMesh m = extractFull(v, 500.0);
  ASSERT_GE(m.triangleCount(), 4u);
  EXPECT_EQ(unmatchedDirectedEdges(m), 0u);
  for (const glm::vec3& p : m.positions)
    EXPECT_LE(glm::length(glm::dvec3(p) - glm::dvec3(9, 6, 11)), 0.5 * std::sqrt(3.0) + 1e-6);
}

TEST(MarchingTetrahedra, ASurfaceTouchingTheVolumeBoundaryIsOpenOnlyThere) {
  // A volume that is not a grid cube (clipped to 13 x 9 x 17 inside 17^3) with a ball at a corner.
  const Dims3 dims{13, 9, 17};
  const IsoMesh m = extractFull(ballVolume(dims, 12.0, 0.0, 8.0), 500.0);
  ASSERT_GT(m.triangleCount(), 0u);
  EXPECT_GT(unmatchedDirectedEdges(m), 0u);
  auto onBoundary = [&](const glm::vec3& p) {
    for (int a = 0; a < 3; ++a)
      if (p[a] == 0.0f || p[a] == static_cast<float>(dims[static_cast<std::size_t>(a)] - 1)) return true;
    return false;
  };
  for (const glm::vec3& p : m.positions)
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(p[a], 0.0f);
      EXPECT_LE(p[a], static_cast<float>(dims[static_cast<std::size_t>(a)] - 1));
    }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (std::size_t t = 0; t < m.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e)
      ++edges[{m.indices[t + static_cast<std::size_t>(e)], m.indices[t + static_cast<std::size_t>((e + 1) % 3)]}];
  for (const auto& [e, count] : edges)
    if (edges.count({e.second, e.first}) == 0) {
      EXPECT_TRUE(onBoundary(m.positions[e.first]) && onBoundary(m.positions[e.second]))
          << "an open edge inside the volume";
    }
}

TEST(MarchingTetrahedra, AnIsovalueOutsideTheDataRangeGivesNoSurface) {
  const Volume<std::uint16_t> v = ballVolume({17, 17, 17}, 8.0, 8.0, 8.0);
  EXPECT_EQ(extractFull(v, 1001.0).triangleCount(), 0u);  // above the maximum: all outside
  EXPECT_EQ(extractFull(v, 0.0).triangleCount(), 0u);     // at the minimum: all inside
  EXPECT_EQ(extractFull(v, -5.0).triangleCount(), 0u);
}

TEST(MarchingTetrahedra, AssemblyGivesVerticesWithoutAGradientTheirTrianglesAreaWeightedNormal) {
  // Store vertices 0..5: 1 is never used; 0, 3 and 4 have no gradient, 2 and 5 have one.
  const std::vector<glm::dvec3> positions{{0, 0, 0}, {9, 9, 9}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {5, 5, 5}};
  const std::vector<glm::dvec3> normals{{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 1, 0}};
  // Triangle (2, 3, 0): cross((-1,2,0), (-1,0,0)) = (0,0,2), its first vertex has a gradient;
  // triangle (0, 4, 2): cross((0,0,3), (1,0,0)) = (0,3,0); triangle (2, 5, 5) has no area and
  // none of its vertices needs it.
  const IsoMesh mesh = assembleIsoMesh({2, 3, 0, 0, 4, 2, 2, 5, 5}, {7, 8, 9}, positions, normals);
  ASSERT_EQ(mesh.positions.size(), 5u);  // in first use: 2, 3, 0, 4, 5
  EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 3, 0, 0, 4, 4}));
  EXPECT_EQ(mesh.triangleDiamond, (std::vector<DiamondId>{7, 8, 9}));
  EXPECT_EQ(mesh.positions[3], glm::vec3(0, 0, 3));
  EXPECT_EQ(mesh.normals[0], glm::vec3(1, 0, 0));  // its gradient
  EXPECT_EQ(mesh.normals[1], glm::vec3(0, 0, 1));  // (0, 0, 2) / 2
  EXPECT_EQ(mesh.normals[2], glm::vec3(0.0f, static_cast<float>(3.0 / std::sqrt(13.0)),
                                       static_cast<float>(2.0 / std::sqrt(13.0))));  // (0, 3, 2) / |.|
  EXPECT_EQ(mesh.normals[3], glm::vec3(0, 1, 0));                                    // (0, 3, 0) / 3
  EXPECT_EQ(mesh.normals[4], glm::vec3(0, 1, 0));                                    // its gradient
  // A vertex without a gradient whose triangles have no area takes +z.
  const IsoMesh flat = assembleIsoMesh({0, 1, 1}, {1}, std::vector<glm::dvec3>{{0, 0, 0}, {1, 1, 1}},
                                       std::vector<glm::dvec3>{{0, 0, 0}, {0, 0, 0}});
  EXPECT_EQ(flat.normals[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(flat.normals[1], glm::vec3(0, 0, 1));
}

}  // namespace
}  // namespace voxref::ref
