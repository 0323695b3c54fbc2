// Which texels a decoder fetched, against the exact decoder's integer addresses
// (reference/timevarying/timevarying_codec.h, addressOfVoxel): a pure comparison. The fetches are
// GL's, measured through the address textures (gpu::measureFetchesGl), or the emulation's.
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

#include "reference/common/plane_frame.h"
#include "reference/common/rgba.h"
#include "reference/timevarying/address_textures.h"
#include "reference/timevarying/timevarying_codec.h"

namespace voxref::conf {

struct FetchCounts {
  std::size_t samples = 0;  // not discarded
  std::size_t right = 0, wrongBlock = 0, wrongVoxel = 0;
  std::size_t wrongColour = 0;  // decoded colour differs from the exact decoder's
  // GL's colour is not the content of the texel its fetch measured, or a pass colour named no texel
  // (only for fetches measured on GL): the measurement cannot account for these samples.
  std::size_t unexplained = 0;
  std::size_t atCoordinateOne = 0, onBlockFace = 0, onVoxelFace = 0, inside = 0;  // wrong fetches by place
  nlohmann::json examples = nlohmann::json::array();                              // the first wrong fetches
  std::size_t wrong() const { return wrongBlock + wrongVoxel; }
  void add(const FetchCounts& o);
  nlohmann::json toJson() const;
};

// `fetches` and the `colours` the decoder returned, per sample of `frame` in its order.
FetchCounts classifyFetches(const ref::TimeVaryingTextures& textures, const ref::TimeSeries& input,
                            const ref::TransferFunction& tf, int step, const ref::PlaneFrame& frame,
                            const std::vector<ref::TexelFetch>& fetches, const std::vector<ref::Rgba8>& colours);

// The colours a decoder returns that fetched `fetches`: each fetched texel's content (0 where discarded).
std::vector<ref::Rgba8> coloursOfFetches(const ref::TimeVaryingTextures& textures,
                                         const std::vector<ref::TexelFetch>& fetches);

// Samples where `gl` is not the content of the texel measured: GL returned something else than
// what its sampler selected in the address textures.
std::size_t unexplainedColours(const std::vector<ref::Rgba8>& fetched, const std::vector<ref::TexelFetch>& fetches,
                               const std::vector<ref::Rgba8>& gl);

// Samples where two records of fetches differ (discard, index texel, flag, or refinement texel of
// a refined sample).
std::size_t differingFetches(const std::vector<ref::TexelFetch>& a, const std::vector<ref::TexelFetch>& b);

}  // namespace voxref::conf
