// Driver fingerprinting (`voxref probe`, issue 6): what a GL driver computes, inferred from the
// read-back bits of the probe frames (reference/common/probe_frames.h) alone, never from
// GL_RENDERER. docs/probe.md describes every probe, its candidates and its evidence.
//
// Every property is decided by the frames of its probe: either a measurement (how many times the
// result changes across one texel; the finest power of two dividing the weights) or a set of
// candidate formulas, each a published rounding rule, of which exactly one must fit every sample
// where the candidates differ. A property whose bits fit no candidate (or more than one) is
// "unknown", with the counts as evidence: a driver voxref has no model for is described, not
// forced into a known one.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "reference/common/probe_frames.h"

namespace voxref::conf {

struct InferredProperty {
  std::string id;        // "sampling.unorm8.subtexel_bits"
  std::string value;     // canonical value (below); "unknown" when the bits fit no single candidate
  std::string evidence;  // the counts the value was decided from, in one sentence
};

// Properties, in this order, and their values:
//   sampling.unorm8.subtexel_bits        "8" (fixed point, n bits) | "float" (finer than 2^-14 texel)
//   sampling.unorm8.coordinate_rounding  u N 2^n to fixed point: "half_even" | "half_up" | "half_down" |
//                                        "floor" | "float" (not fixed point)
//   sampling.unorm8.lerp_rounding        "nearest" a + ((w (b - a) + 2^(n-1)) >> n) | "floor"
//                                        a + ((w (b - a)) >> n) | "float" (results between codes)
//   sampling.float.subtexel_bits         as for unorm8, for RGBA32F textures
//   sampling.float.lerp                  "fused" fma(w, b - a, a) | "unfused" a + fl(w (b - a))
//   sampling.float.repeat_scaling        REPEAT on 3 texels at u near 7.25: "fract_then_scale"
//                                        fract(u) * N (llvmpipe) | "scale_then_floor" u * N, then
//                                        floor and wrap (softpipe)
//   sampling.float.denormals             "flushed" | "kept" (denormal texels of an RGBA32F texture)
//   store.unorm8_rounding                float to unorm8 of a shader output: "half_even" | "half_up" | "floor"
//   store.unorm16_rounding               the same for unorm16
//   framebuffer.between_passes           "requantized" (every blend reads the stored code) |
//                                        "float_tile_cache" (float kept until the read-back)
//   blend.rgba8_src_alpha                SRC_ALPHA / ONE_MINUS_SRC_ALPHA on RGBA8: "mulnorm"
//                                        (t + (t >> 8) + 128) >> 8 | "exact" round(x y / 255) |
//                                        "float" (blend in float32, round once when stored)
struct DriverFingerprint {
  std::vector<InferredProperty> properties;
  const InferredProperty* find(std::string_view id) const;  // nullptr for an unknown id
};

// `frames` in the design's order (sweeps, then writes), as gpu::renderProbeFramesGl and
// emu::emulateProbeFrames give them. Throws std::invalid_argument when a frame is missing or its
// size or format is not the design's. Safe on any codes (untrusted read-backs): odd bits give
// "unknown" values, never a crash.
DriverFingerprint inferFingerprint(const ref::ProbeDesign& design, std::span<const ref::ProbeFrame> frames);

}  // namespace voxref::conf
