// Tests of the isosurface renderer kept across frames (label `gl`): a renderer that loads mesh
// after mesh, smaller and larger than the one before, gives the images and query results of a
// renderer made for each mesh alone, so nothing of an earlier mesh survives in its buffers.
#include "gpu/iso_gl.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "tests/gpu/llvmpipe_suite.h"

#include "gpu/context.h"
#include "reference/common/view_camera.h"

namespace voxref::gpu {
namespace {

class IsoGl : public LlvmpipeSuite {};

ref::ViewCamera camera(int width, int height) {
  ref::ViewCamera c;
  c.eye = {0.0, 0.0, 10.0};
  c.target = {0.0, 0.0, 0.0};
  c.up = {0.0, 1.0, 0.0};
  c.fovYDegrees = 60.0;
  c.width = width;
  c.height = height;
  c.nearPlane = 0.5;
  c.farPlane = 50.0;
  return c;
}

// `n` squares side by side along x (two triangles each), tilted in depth so that the triangles
// overlap in depth order differently for different n, at depth z.
ref::IsoMesh strip(int n, float z) {
  ref::IsoMesh m;
  for (int i = 0; i < n; ++i) {
    const float x0 = -4.0f + 8.0f * static_cast<float>(i) / static_cast<float>(n),
                x1 = x0 + 8.0f / static_cast<float>(n);
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    m.positions.insert(m.positions.end(), {{x0, -2.0f, z}, {x1, -2.0f, z + 0.5f}, {x1, 2.0f, z}, {x0, 2.0f, z - 0.5f}});
    m.normals.insert(m.normals.end(), 4, glm::vec3(0.0f, 0.0f, 1.0f));
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    m.triangleDiamond.insert(m.triangleDiamond.end(), 2, 0);
  }
  return m;
}

void expectSameImage(const IsoImageGl& a, const IsoImageGl& b, const std::string& what) {
  EXPECT_EQ(a.width, b.width) << what;
  EXPECT_EQ(a.height, b.height) << what;
  EXPECT_EQ(a.rgba, b.rgba) << what;
  EXPECT_EQ(a.primitive, b.primitive) << what;
  EXPECT_EQ(a.windowDepth, b.windowDepth) << what;
}

// What a reused renderer is given in turn: meshes larger, smaller (the buffers keep their storage),
// empty, then larger than any before (they grow); the last camera changes the target's size.
struct Load {
  ref::IsoMesh mesh;
  ref::ViewCamera camera;
};
std::vector<Load> loadsInTurn() {
  return {{strip(20, 0.0f), camera(64, 48)},
          {strip(3, 1.0f), camera(64, 48)},
          {ref::IsoMesh{}, camera(64, 48)},
          {strip(57, -1.0f), camera(40, 30)}};
}
// Loads each of loadsInTurn() into `renderer` in turn and calls check(i, mesh, camera) after each.
template <class Check>
void afterEachLoad(IsoMeshRenderer& renderer, Check&& check) {
  const std::vector<Load> loads = loadsInTurn();
  for (std::size_t i = 0; i < loads.size(); ++i) {
    renderer.load(loads[i].mesh);
    check(i, loads[i].mesh, loads[i].camera);
  }
}

TEST_F(IsoGl, AReusedRendererDrawsEachMeshAsAFreshOneDoes) {
  IsoMeshRenderer renderer(*context_);
  afterEachLoad(renderer, [&](std::size_t i, const ref::IsoMesh& mesh, const ref::ViewCamera& view) {
    const IsoImageGl reused = renderer.render(view);
    const IsoImageGl fresh = renderIsoMeshGl(*context_, mesh, view);
    expectSameImage(reused, fresh, "mesh " + std::to_string(i));
    // The image shows the mesh: triangles of this mesh were drawn (ids up to its count), none beyond.
    std::uint32_t highest = 0;
    for (std::uint32_t id : reused.primitive) highest = std::max(highest, id);
    EXPECT_EQ(highest == 0, mesh.indices.empty()) << "mesh " << i;
    EXPECT_LE(highest, mesh.triangleCount()) << "mesh " << i;
  });
}

// display() draws the frame's image with a program of its own (iso_mesh_display.frag), the same
// shading function without gl_PrimitiveID: on llvmpipe, the same colours as render()'s, pixel for
// pixel, for each mesh; and a display in between leaves render()'s images as a fresh renderer's.
TEST_F(IsoGl, ADisplayedFrameIsTheColourOfTheOraclesImage) {
  IsoMeshRenderer renderer(*context_);
  afterEachLoad(renderer, [&](std::size_t i, const ref::IsoMesh& mesh, const ref::ViewCamera& view) {
    const std::vector<std::array<std::uint8_t, 4>> shown = renderer.display(view);
    const IsoImageGl judged = renderer.render(view);
    EXPECT_EQ(shown, judged.rgba) << "mesh " << i;
    const std::size_t lit =
        std::count_if(shown.begin(), shown.end(), [](const std::array<std::uint8_t, 4>& p) { return p[3] != 0; });
    EXPECT_EQ(lit == 0, mesh.indices.empty()) << "mesh " << i;
    (void)renderer.display(view);
    expectSameImage(renderer.render(view), renderIsoMeshGl(*context_, mesh, view),
                    "mesh " + std::to_string(i) + " after a display");
  });
}

TEST_F(IsoGl, QueriesTestAgainstTheMeshLoadedLast) {
  IsoMeshRenderer renderer(*context_);
  const ref::ViewCamera c = camera(64, 48);
  // Boxes behind the strip (hidden by it), in front of it, and beside it.
  const std::vector<QueryBox> boxes = {{{-1.0, -1.0, -4.0}, {1.0, 1.0, -3.0}},
                                       {{-1.0, -1.0, 2.0}, {1.0, 1.0, 3.0}},
                                       {{6.0, -1.0, -4.0}, {7.0, 1.0, -3.0}}};
  const ref::IsoMesh wall = strip(8, 0.0f), none;
  renderer.load(wall);
  (void)renderer.render(c);  // a frame drawn in between, as in a frame loop
  const std::vector<std::uint32_t> behindWall = renderer.occlusionQueries(boxes, c);
  EXPECT_EQ(behindWall, occlusionQueriesGl(*context_, wall, boxes, c));
  EXPECT_EQ(behindWall, renderer.occlusionQueries(boxes, c, SampleCounter::Buffer));
  EXPECT_EQ(behindWall[0], 0u);
  EXPECT_GT(behindWall[1], 0u);
  EXPECT_GT(behindWall[2], 0u);
  renderer.load(none);
  const std::vector<std::uint32_t> open = renderer.occlusionQueries(boxes, c);
  EXPECT_EQ(open, occlusionQueriesGl(*context_, none, boxes, c));
  EXPECT_GT(open[0], 0u);
}

// The counts themselves, derived apart from GL: a box straddling a wall, seen head on, has one
// face toward the eye (z = 2, in front of the wall); its samples are the pixel centres inside that
// face's projection, a rectangle computed here in double. Drawing the back faces as well would add
// the sides' parts in front of the wall; drawing them instead would give those parts alone.
TEST_F(IsoGl, ABoxCountsTheSamplesOfItsFrontFacesByEitherCounter) {
  const ref::ViewCamera c = camera(64, 48);
  const QueryBox box{{-1.0, -1.0, -2.0}, {1.0, 1.0, 2.0}};
  const glm::dmat4 mvp = ref::projectionMatrix(c) * ref::viewMatrix(c);
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const double x : {box.lo[0], box.hi[0]})
    for (const double y : {box.lo[1], box.hi[1]}) {
      const glm::dvec4 clip = mvp * glm::dvec4(x, y, box.hi[2], 1.0);
      const double window[2] = {(clip.x / clip.w + 1.0) * 0.5 * c.width, (clip.y / clip.w + 1.0) * 0.5 * c.height};
      for (int a = 0; a < 2; ++a) {
        lo[a] = std::min(lo[a], window[a]);
        hi[a] = std::max(hi[a], window[a]);
      }
    }
  std::uint32_t inside[2] = {0, 0};  // pixel centres inside the rectangle, per axis
  for (int a = 0; a < 2; ++a)
    for (int i = 0; i < (a == 0 ? c.width : c.height); ++i) {
      const double centre = i + 0.5;
      ASSERT_GT(std::min(std::abs(centre - lo[a]), std::abs(centre - hi[a])), 1e-3) << "a centre on an edge";
      inside[a] += centre > lo[a] && centre < hi[a];
    }
  const std::uint32_t expected = inside[0] * inside[1];
  ASSERT_GT(expected, 50u);
  const ref::IsoMesh wall = strip(8, 0.0f);
  for (const SampleCounter counter : {SampleCounter::Queries, SampleCounter::Buffer})
    EXPECT_EQ(occlusionQueriesGl(*context_, wall, {box}, c, counter), std::vector<std::uint32_t>{expected})
        << name(counter);
}

// The two counters agree box for box on boxes hidden, half hidden and in the open, and on boxes
// too near the eye to test.
TEST_F(IsoGl, TheTwoCountersCountTheSameSamples) {
  const ref::ViewCamera c = camera(96, 64);
  std::mt19937 random(18);
  std::uniform_real_distribution<double> at(-5.0, 5.0), size(0.05, 2.0), depth(-4.0, 9.8);
  std::vector<QueryBox> boxes;
  for (int i = 0; i < 300; ++i) {
    QueryBox b;
    for (int a = 0; a < 3; ++a) {
      b.lo[static_cast<std::size_t>(a)] = a == 2 ? depth(random) : at(random);
      b.hi[static_cast<std::size_t>(a)] = b.lo[static_cast<std::size_t>(a)] + size(random);
    }
    boxes.push_back(b);
  }
  IsoMeshRenderer renderer(*context_);
  renderer.load(strip(13, 0.5f));
  const std::vector<std::uint32_t> byQueries = renderer.occlusionQueries(boxes, c, SampleCounter::Queries);
  EXPECT_EQ(byQueries, renderer.occlusionQueries(boxes, c, SampleCounter::Buffer));
  EXPECT_TRUE(renderer.occlusionQueries({}, c, SampleCounter::Buffer).empty());
  EXPECT_TRUE(renderer.occlusionQueries({}, c, SampleCounter::Queries).empty());
  std::size_t hidden = 0, seen = 0, untested = 0;
  for (std::uint32_t n : byQueries) (n == 0 ? hidden : n == kNotTested ? untested : seen) += 1;
  EXPECT_GT(hidden, 10u);  // the comparison covers every kind of box
  EXPECT_GT(seen, 10u);
  EXPECT_GT(untested, 0u);
}

}  // namespace
}  // namespace voxref::gpu
