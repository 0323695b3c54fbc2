// Which texels a decoder fetched, against the exact decoder's integer addresses
// (reference/timevarying/timevarying_codec.h, addressOfVoxel): a pure comparison.
//
// The voxel a sample p stands for is floor(p * side) per axis, clamped to side - 1 (GL's
// CLAMP_TO_EDGE at p = 1.0); its right colour is the input after the transfer function (not the
// textures' content, which the paper's alpha-one policy can corrupt). A fetch is right when it
// reads that voxel's index texel and, for a refined cell, its refinement texel (a flag whose
// address lies outside the textures counts as a wrong block); a wrong block when it reads another index texel or
// another block slot; a wrong voxel when it reads the right block but another voxel of it. Wrong fetches are counted by
// where the sample lies: at coordinate 1.0, on a block face (p * side a multiple of the block side), on a voxel face (p
// * side an integer), or inside.
#pragma once

#include <cstddef>

#include <nlohmann/json.hpp>

#include "emulation/timevarying_emu.h"
#include "reference/common/plane_frame.h"
#include "reference/timevarying/timevarying_codec.h"

namespace voxref::conf {

struct FetchCounts {
  std::size_t samples = 0;  // not discarded
  std::size_t right = 0, wrongBlock = 0, wrongVoxel = 0;
  std::size_t wrongColour = 0;  // decoded colour differs from the exact decoder's
  std::size_t atCoordinateOne = 0, onBlockFace = 0, onVoxelFace = 0, inside = 0;  // wrong fetches by place
  nlohmann::json examples = nlohmann::json::array();                              // the first wrong fetches
  std::size_t wrong() const { return wrongBlock + wrongVoxel; }
  void add(const FetchCounts& o);
  nlohmann::json toJson() const;
};

FetchCounts classifyFetches(const ref::TimeVaryingTextures& textures, const ref::TimeSeries& input,
                            const ref::TransferFunction& tf, int step, const ref::PlaneFrame& frame,
                            const emu::EmulatedDecode& decoded);

}  // namespace voxref::conf
