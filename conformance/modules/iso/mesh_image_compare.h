// GL's image of an extracted mesh against Embree's image of the same mesh (fixtures/): one pure
// comparison whose allowances are derived, triangle by triangle.
//
// GL reports, per pixel, the triangle it drew (gl_PrimitiveID) and its window depth; Embree the
// triangle its float32 ray through the pixel centre hit first. Every claim is checked against the
// mesh itself, in double:
//   coverage   GL may draw triangle g at a pixel only if the pixel centre lies inside g's
//              projection or within kSnapPixels of it: GL snaps vertices to its sub-pixel grid
//              (8 bits on llvmpipe and softpipe; GL 4.6 section 14.5 requires at least 4, 1/16 px)
//              and transforms them in float32, which together move an edge by less than 1/64 px at
//              these image sizes. GL may leave a pixel empty only if Embree's triangle (if any) is
//              within kSnapPixels of the centre's edge side.
//   depth      GL's depth (the window depth inverted to eye depth) must equal the depth of g's plane
//              on the pixel ray within  8 ulp of the float32 window depth mapped to eye depth (the
//              DEPTH32F store and the perspective interpolation)  + kSnapPixels x the plane's eye-depth
//              slope per pixel (the same snapping)  + 2^-20 z (float32 vertex transform).
//   visibility where Embree's triangle e covers the centre by more than kSnapPixels, GL must have
//              drawn e or a triangle g in front of it (plane depth not behind e's beyond the depth
//              allowance); a g that covers by more than kSnapPixels and differs from e must be
//              coincident with e in depth (Embree would have seen it otherwise).
// Everything else is a failure with its count. Embree's float32 ray and robust traversal are
// within the same allowances (fixtures/raycast/mesh_raycast.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "fixtures/raycast/ray_image.h"
#include "gpu/iso_gl.h"
#include "reference/common/view_camera.h"
#include "reference/iso/iso_mesh.h"

namespace voxref::conf {

inline constexpr double kSnapPixels = 1.0 / 64.0;

enum class MeshPixelFailure : std::uint8_t { None = 0, Coverage = 1, Depth = 2, Visibility = 3 };

// One judged pixel, for the report's magnified view: GL's eye depth (NaN where GL drew nothing),
// Embree's (+infinity on a miss), and the depth allowance around the plane of GL's triangle.
struct MeshPixel {
  int x = 0, y = 0;
  MeshPixelFailure failure = MeshPixelFailure::None;
  double glDepth = 0.0, truthDepth = 0.0;
  double planeDepth = 0.0, allowance = 0.0;  // NaN where GL drew nothing or its triangle was not reached
};

struct MeshImageAgreement {
  std::vector<MeshPixelFailure> failure;  // per pixel, x + width * y (row 0 at the bottom)
  // At most kMaxWorstPixels: failures first (depth failures farthest beyond their allowance
  // first), then the drawn pixels whose depth difference uses most of its allowance.
  std::vector<MeshPixel> worst;
  std::size_t pixels = 0, sameTriangle = 0, otherTriangleAllowed = 0;
  std::size_t coverageFailures = 0, depthFailures = 0, visibilityFailures = 0;
  double maxDepthDifference = 0.0;  // eye units, GL depth against its own triangle's plane
  double maxDepthOverBound = 0.0;   // the worst |difference| / allowance
  bool pass() const { return coverageFailures == 0 && depthFailures == 0 && visibilityFailures == 0; }
};

// Eye depth of a GL window depth (the inverse of ref::windowDepth).
double eyeDepthOfWindowDepth(const ref::ViewCamera& camera, double windowDepth);

MeshImageAgreement compareMeshImages(const ref::IsoMesh& mesh, const gpu::IsoImageGl& gl, const fx::RayImage& truth,
                                     const ref::ViewCamera& camera);

}  // namespace voxref::conf
