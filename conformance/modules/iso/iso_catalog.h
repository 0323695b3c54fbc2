// The conformance cases of the isosurface system (Gregorski et al. 2004, part 2):
//   iso.frames.<scene>    every frame of the scene's orbit, with occlusion culling:
//                         occlusion   no diamond the ground truth (Embree item buffer of the
//                                     frame's mesh) sees was culled; efficiency reported;
//                         mesh_image  GL's image of each frame's mesh against Embree's image of the
//                                     same mesh, under the derived bound of mesh_image_compare.h;
//                         sample_counters  every occlusion test counted by GL_SAMPLES_PASSED queries
//                                     and by a storage buffer (gpu/iso_gl.h), equal box for box;
//   iso.accuracy.<scene>  the extracted surface against the exact isosurface of the trilinear field
//                         (Embree), per error threshold: depth error, silhouette difference,
//                         triangles and extraction time: what accuracy costs (information);
//   iso.hard.<name>       the hard cases of hardIsoScenes() through the frame loop.
#pragma once

#include <vector>

#include "conformance/framework/case.h"

namespace voxref::conf {

std::vector<Case> isoCases();

}  // namespace voxref::conf
