// The frame loop of the isosurface system (Gregorski et al. 2004, sections 4 and 5), with its
// ground truth: per frame of a scene's scripted orbit,
//   1. occlusion culling as the paper does it: the previous frame's surface is rendered for depth
//      from the new camera, and the bounding boxes of the diamonds in the split and merge queues
//      (those whose range holds the isovalue) are tested with GL occlusion queries; a diamond
//      found visible is tested again only after `retestVisibleEvery` frames; a change of isovalue
//      invalidates the occluders (no culling that frame);
//   2. view-dependent refinement, occluded diamonds counting as error zero;
//   3. extraction from the compressed stream (pages decoded on demand), incremental: only the
//      leaf tetrahedra that were not leaves the frame before are read (reference/iso/
//      incremental_extraction.h; the same mesh as extracting the whole mesh again);
//   4. the GL image of the mesh as a display shows it (timed: IsoMeshRenderer::display); then,
//      for the oracles and outside the frame's time, its GL image with primitive ids and depth
//      (render) and Embree's image of the same mesh (fixtures/), whose item buffer says which
//      diamonds are visible: the ground truth the culling is judged by.
// Query boxes are the diamonds' boxes clipped to the volume and grown by kQueryBoxMargin grid
// units on every side: DEPTH32F quantizes window depth to 2^-24 near 1, which at the scenes'
// distances (z <= 4 radii, n = 0.5) is below 1e-3 grid units of eye depth, so the margin keeps a
// surface lying on a box face from hiding its own box.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "conformance/modules/iso/iso_scene.h"
#include "conformance/modules/iso/sample_count_compare.h"
#include "fixtures/raycast/ray_image.h"
#include "gpu/context.h"
#include "gpu/iso_gl.h"
#include "reference/iso/diamond_bounds.h"
#include "reference/iso/grid_field.h"
#include "reference/iso/iso_mesh.h"

namespace voxref::conf {

inline constexpr double kQueryBoxMargin = 0.05;

struct IsoFrame {
  int frame = 0;
  double isovalue = 0.0;
  ref::ViewCamera camera;
  ref::RefinementStats refinement;
  std::size_t occlusionTests = 0, culled = 0;
  std::size_t revokedCulls = 0;         // culls undone by the verification pass (IsoScene::verifyCulls)
  std::size_t falseCulls = 0;           // culled, yet visible in the ground truth
  std::size_t invisibleCandidates = 0;  // queue diamonds holding the isovalue, not visible in the ground truth
  std::size_t culledInvisible = 0;
  std::size_t visibleDiamonds = 0, triangles = 0, leafTetrahedra = 0;
  std::uint64_t pagesDecoded = 0;  // cumulative
  SampleCountComparison counters;  // IsoRunOptions::compareCounters: the tests counted both ways
  double secondsQueries = 0, secondsRefine = 0, secondsExtract = 0, secondsGl = 0, secondsEmbree = 0;
  ref::IsoMesh mesh;
  gpu::IsoImageGl gl;
  fx::RayImage truth;
};

struct IsoRunOptions {
  bool keepImages = false;  // keep mesh and images of every frame (else only of the last)
  int threads = 0;
  std::function<void(int)> progress;
  gpu::SampleCounter counter = gpu::SampleCounter::Queries;  // how the occlusion tests count samples
  // Every occlusion test counted by the other counter as well, outside the frame's timings, and the
  // two compared (IsoFrame::counters). Throws GlUnsupported where the context lacks the buffer counter.
  bool compareCounters = false;
};

// Throws what the layers throw (GL errors, Embree errors, invalid scenes).
std::vector<IsoFrame> runIsoFrames(gpu::Context& gl, const IsoScene& scene, const IsoRunOptions& options);
// The same frames from a stream already made and its bounds (the full table, or tiered bounds
// over this field): the scene gives the isovalue, orbit, camera, budget and culling, not the
// volume. For volumes too large to hold (the bounds and the field's caches are all it keeps).
// Throws std::invalid_argument when the bounds' grid is not the field's.
std::vector<IsoFrame> runIsoFrames(gpu::Context& gl, const IsoScene& scene, ref::CompressedGridField& field,
                                   const ref::DiamondRanges& bounds, const IsoRunOptions& options);

}  // namespace voxref::conf
