#include "conformance/modules/iso/mesh_image_compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "conformance/framework/case.h"
#include "conformance/framework/report/worst_samples.h"

namespace voxref::conf {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct ScreenTriangle {
  bool projectable = false;  // every vertex in front of the eye
  glm::dvec2 p[3];           // window coordinates in pixels
  glm::dvec3 a, normal;      // the plane, world space
};

// Signed distance in pixels from c to the triangle's projection: positive inside (distance to the
// nearest edge), negative outside. Degenerate projections count as outside.
double coverage(const ScreenTriangle& t, const glm::dvec2& c) {
  const double area = (t.p[1].x - t.p[0].x) * (t.p[2].y - t.p[0].y) - (t.p[1].y - t.p[0].y) * (t.p[2].x - t.p[0].x);
  if (area == 0.0) return -kInf;
  double inside = kInf;
  bool in = true;
  for (int e = 0; e < 3; ++e) {
    const glm::dvec2 u = t.p[e], v = t.p[(e + 1) % 3];
    const glm::dvec2 d = v - u;
    const double len = glm::length(d);
    const double side = (d.x * (c.y - u.y) - d.y * (c.x - u.x)) / len * (area > 0 ? 1.0 : -1.0);
    inside = std::min(inside, side);
    if (side < 0.0) in = false;
  }
  if (in) return inside;
  // Outside: the distance to the closest point of the triangle (the nearest edge segment).
  double outside = kInf;
  for (int e = 0; e < 3; ++e) {
    const glm::dvec2 u = t.p[e], v = t.p[(e + 1) % 3];
    const glm::dvec2 d = v - u;
    const double s = std::clamp(glm::dot(c - u, d) / std::max(glm::dot(d, d), 1e-300), 0.0, 1.0);
    outside = std::min(outside, glm::length(c - (u + s * d)));
  }
  return -outside;
}

// Eye depth of the plane of t along the ray of window point c (kInf when parallel or behind).
double planeDepth(const ScreenTriangle& t, const ref::ViewCamera& cam, const glm::dvec2& c) {
  const ref::Ray r = ref::pixelRay(cam, c.x, c.y);
  const double denom = glm::dot(t.normal, r.direction);
  if (denom == 0.0) return kInf;
  const double s = glm::dot(t.normal, t.a - r.origin) / denom;
  if (s <= 0.0) return kInf;
  return ref::eyeDepth(cam, r.origin + s * r.direction);
}

}  // namespace

double eyeDepthOfWindowDepth(const ref::ViewCamera& c, double wd) {
  const double n = c.nearPlane, f = c.farPlane;
  const double ndc = 2.0 * wd - 1.0;
  return 2.0 * f * n / ((f + n) - ndc * (f - n));
}

MeshImageAgreement compareMeshImages(const ref::IsoMesh& mesh, const gpu::IsoImageGl& gl, const fx::RayImage& truth,
                                     const ref::ViewCamera& camera) {
  if (gl.width != truth.width || gl.height != truth.height)
    throw std::invalid_argument("mesh images of different sizes");
  const glm::dmat4 mvp = ref::projectionMatrix(camera) * ref::viewMatrix(camera);
  std::vector<ScreenTriangle> tris(mesh.triangleCount());
  for (std::size_t t = 0; t < tris.size(); ++t) {
    ScreenTriangle& s = tris[t];
    s.projectable = true;
    glm::dvec3 v[3];
    for (int k = 0; k < 3; ++k) {
      v[k] = glm::dvec3(mesh.positions[mesh.indices[3 * t + static_cast<std::size_t>(k)]]);
      const glm::dvec4 clip = mvp * glm::dvec4(v[k], 1.0);
      if (clip.w <= camera.nearPlane * 0.5) s.projectable = false;
      s.p[k] = {(clip.x / clip.w + 1.0) * 0.5 * camera.width, (clip.y / clip.w + 1.0) * 0.5 * camera.height};
    }
    s.a = v[0];
    s.normal = glm::cross(v[1] - v[0], v[2] - v[0]);
  }
  MeshImageAgreement a;
  const std::size_t count = static_cast<std::size_t>(gl.width) * static_cast<std::size_t>(gl.height);
  a.failure.assign(count, MeshPixelFailure::None);
  std::vector<MeshPixel> judged(count);
  // Ranking for `worst`: failures by how far beyond the allowance (at least 1), agreeing pixels
  // by the share of the allowance they use.
  std::vector<double> failScore(count, 0.0), passScore(count, 0.0);
  auto fail = [&](std::size_t i, MeshPixelFailure f, std::size_t& counter) {
    ++counter;
    a.failure[i] = judged[i].failure = f;
    const double over = std::fabs(judged[i].glDepth - judged[i].planeDepth) / judged[i].allowance;
    failScore[i] = std::isfinite(over) ? std::max(over, 1.0) : 1.0;
  };
  for (int y = 0; y < gl.height; ++y)
    for (int x = 0; x < gl.width; ++x) {
      const std::size_t i =
          static_cast<std::size_t>(x) + static_cast<std::size_t>(gl.width) * static_cast<std::size_t>(y);
      ++a.pixels;
      const glm::dvec2 c(x + 0.5, y + 0.5);
      const bool hasG = gl.primitive[i] != 0, hasE = truth.primitive[i] != fx::kNoHit;
      const std::size_t g = hasG ? gl.primitive[i] - 1 : 0, e = hasE ? truth.primitive[i] : 0;
      judged[i] = {x,
                   y,
                   MeshPixelFailure::None,
                   hasG ? eyeDepthOfWindowDepth(camera, gl.windowDepth[i]) : std::nan(""),
                   static_cast<double>(truth.depth[i]),
                   std::nan(""),
                   std::nan("")};
      if ((hasG && g >= tris.size()) || (hasE && e >= tris.size())) {
        fail(i, MeshPixelFailure::Coverage, a.coverageFailures);  // an id that is not a triangle of the mesh
        continue;
      }
      if ((hasG && !tris[g].projectable) || (hasE && !tris[e].projectable))
        continue;  // crosses the eye plane: not judged
      const double coverE = hasE ? coverage(tris[e], c) : -kInf;
      double allowance = 0.0, zG = kInf;
      if (hasG) {
        const double coverG = coverage(tris[g], c);
        if (coverG < -kSnapPixels) {
          fail(i, MeshPixelFailure::Coverage, a.coverageFailures);
          continue;
        }
        zG = planeDepth(tris[g], camera, c);
        const double wd = gl.windowDepth[i];
        const double ulp = static_cast<double>(std::nextafter(static_cast<float>(wd), 2.0f)) - static_cast<float>(wd);
        const double zGl = judged[i].glDepth;
        const double slope = std::hypot(planeDepth(tris[g], camera, c + glm::dvec2(1, 0)) - zG,
                                        planeDepth(tris[g], camera, c + glm::dvec2(0, 1)) - zG);
        allowance = 8.0 * std::fabs(eyeDepthOfWindowDepth(camera, wd + ulp) - zGl) +
                    kSnapPixels * (std::isfinite(slope) ? slope : kInf) + 0x1p-20 * std::fabs(zG);
        judged[i].planeDepth = zG;
        judged[i].allowance = allowance;
        const double diff = std::fabs(zGl - zG);
        a.maxDepthDifference = std::max(a.maxDepthDifference, diff);
        a.maxDepthOverBound = std::max(a.maxDepthOverBound, diff / allowance);
        passScore[i] = diff / allowance;
        if (diff > allowance) {
          fail(i, MeshPixelFailure::Depth, a.depthFailures);
          continue;
        }
        if (hasE && g == e) {
          ++a.sameTriangle;
          continue;
        }
        if (hasE && coverE > kSnapPixels) {  // Embree's triangle surely covers: GL's must be in front
          const double zE = planeDepth(tris[e], camera, c);
          const bool inFront = zG <= zE + allowance;
          const bool marginalOrCoincident = coverG <= kSnapPixels || std::fabs(zG - zE) <= allowance;
          if (!inFront || !marginalOrCoincident) {
            fail(i, MeshPixelFailure::Visibility, a.visibilityFailures);
            continue;
          }
        }
        ++a.otherTriangleAllowed;
        continue;
      }
      if (hasE && coverE > kSnapPixels)
        fail(i, MeshPixelFailure::Coverage,
             a.coverageFailures);  // GL left empty a pixel Embree's triangle surely covers
    }
  for (std::size_t i : largestScores(failScore, kMaxWorstPixels)) a.worst.push_back(judged[i]);
  for (std::size_t i : largestScores(passScore, kMaxWorstPixels))
    if (a.worst.size() < kMaxWorstPixels && a.failure[i] == MeshPixelFailure::None) a.worst.push_back(judged[i]);
  return a;
}

}  // namespace voxref::conf
