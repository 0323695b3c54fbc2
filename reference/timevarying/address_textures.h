// Address textures: copies of the index and refinement textures whose every texel holds its own
// coordinates instead of its content (reference/timevarying/FORMAT.md, "Address textures"). A
// decoder run on GL with one of them in place of the real texture writes, where it would have
// written the fetched texel's colour, the coordinates of the texel it fetched: what the driver's
// sampler selected, measured, on any driver and through any decoder shader, without changing the
// shader or the textures' formats, sizes or sampler state.
//
// Code of texel (i, j, k), RGBA8: R = i mod 256, G = j mod 256, B = k mod 256,
// A = 64 + (i / 256) + 4 (j / 256) + 16 (k / 256), so 64 to 127: never the refinement flag (alpha
// at maximum), and every decoder passes such a texel through as a colour. Extents up to 1024 per
// axis. A colour of zero names no texel: a texelFetch outside the texture, whose result GL leaves
// undefined (GL 4.6 section 11.1.3.2) and many drivers return as zero (kNoTexel).
// In an index texture the code is stored in the index's encoding (unorm16: 257 code; float:
// code / 255 as binary32), which every encoding maps back to the same RGBA8 code.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "reference/common/plane_frame.h"
#include "reference/common/rgba.h"
#include "reference/timevarying/timevarying_codec.h"

namespace voxref::ref {

inline constexpr int kMaxAddressableExtent = 1024;
// No texel: the fetch lay outside the texture and returned zero.
inline constexpr std::array<int, 3> kNoTexel{-1, -1, -1};

Rgba8 addressCode(const std::array<int, 3>& texel);
// The texel a code names (kNoTexel for zero); nullopt for a colour that is no address code.
std::optional<std::array<int, 3>> texelOfAddressCode(const Rgba8& code);

// Same encoding and extents, every texel its address code. Throw std::length_error for an
// extent over kMaxAddressableExtent (the message names the texture and its extents).
IndexTexture addressIndexTexture(const IndexTexture& index);
RefinementTexture addressRefinementTexture(const RefinementTexture& refinement);

// What a decoder fetched for one sample of a plane frame.
struct TexelFetch {
  bool discarded = false;                              // outside the unit cube: nothing fetched
  bool refined = false;                                // the fetched index texel carries the refinement flag
  std::array<int, 3> indexTexel{}, refinementTexel{};  // the texels read (kNoTexel: none, zero returned)
};

// The fetches of every sample of `frame` (x fastest, then y, then plane), from two decode-planes
// renders of one step: `indexPass` with the index texture's address texture in place of the index,
// `refinementPass` with the refinement texture's address texture in place of the refinement
// texture. A sample is refined when the index texel it fetched carries the flag (its content in
// `textures`); then its refinement pass colour names the refinement texel. `unreadable` counts
// samples whose pass colour is no address code (a decoder that does not return the fetched texel
// as it is); those are recorded as discarded. Throws std::invalid_argument when the passes do not
// hold one colour per sample.
struct MeasuredFetches {
  std::vector<TexelFetch> fetches;
  std::size_t unreadable = 0;
};
MeasuredFetches fetchesFromAddressPasses(const TimeVaryingTextures& textures, const PlaneFrame& frame,
                                         const RgbaStack& indexPass, const RgbaStack& refinementPass);

// The colour a decoder returns when it fetched `f`: the texel's content as RGBA8 (zero for kNoTexel).
Rgba8 colourOfFetch(const TimeVaryingTextures& textures, const TexelFetch& f);

}  // namespace voxref::ref
