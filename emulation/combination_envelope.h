// The envelope of the paper's hardware method: for one sample, the interval of stored colour
// values that any conforming GL implementation may read back after all passes, propagated pass
// by pass from the texture envelope (texture_envelope.h).
//
// Per pass (sources given beside each rule):
//  - the source value: the texture envelope widened by dEQP's colour threshold, 2^-(bits - 2)
//    for LINEAR and 2^-(bits - 1) for NEAREST, where bits is the lower of the target's and the
//    texture's colour bits (unorm bits, or mantissa bits for float formats: 10 for half, 23 for
//    float): a lookup cannot be more precise than its texels (llvmpipe filters unorm8 in 8 bits);
//  - blending (GL 4.6 section 17.3.6): fixed-point targets clamp the source to [0, 1], compute
//    dst + src or dst - src "as if in floating point", clamp to [0, 1] and convert to fixed point
//    with either of the two nearest codes (section 2.3.5.2, convert_float_uint); float targets
//    do not clamp and may round the sum to either neighbouring representable value;
//  - the destination is the stored value of the previous pass (0 after the clear).
// Every operation is monotone in each argument, so propagating interval end points is exact.
//
// With arithmetic the probe measured (measured_arithmetic.h; derivations in docs/oracles.md,
// "Envelopes from measured arithmetic") two rules tighten, and nothing else changes:
//  - float filtering of a non-unorm8 texture: the colour threshold becomes 2^-20 max(1, |texel|max)
//    (texel conversion and seven float lerps: at most 8 roundings of 2^-24 relative, carried with
//    weights summing to one) and the subtexel bits 24 - ceil(log2 N) for the largest extent N
//    (the weight's error is that of the float u N), at least dEQP's 7; a quality warning allows 3
//    bits fewer;
//  - an 8-bit store that rounds to nearest (or down) in every pass: the stored code of a real
//    value x is the nearest code (or the one below), with 2^-16 code of slack either side for the
//    float product x 255 (relative error 2^-24), instead of either neighbouring code.
#pragma once

#include <string>
#include <vector>

#include "emulation/measured_arithmetic.h"
#include "emulation/texture_envelope.h"
#include "reference/common/plane_frame.h"
#include "reference/sparsegrid/combination_textures.h"

namespace voxref::emu {

class CombinationEnvelope {
 public:
  CombinationEnvelope(const ref::CombinationTextures& textures, const ref::PlaneFrame& frame,
                      const ref::SamplerState& sampler, ref::FramebufferFormat format,
                      const MeasuredArithmetic& measured = {});
  // The stored values (decoded exactly, framebuffer_codes.h) allowed at sample (i, j, k).
  Interval at(int i, int j, int k, const EnvelopePrecision& precision) const;
  // The colour threshold applied to every pass's source value, and its derivation.
  double colourThreshold() const { return threshold_; }
  // The precision of a pass and of a quality warning: dEQP's (kEnvelopePass, kEnvelopeQualityWarning),
  // or from the measured float filtering.
  const EnvelopePrecision& passPrecision() const { return pass_; }
  const EnvelopePrecision& warningPrecision() const { return warning_; }
  // Which measured rules this envelope uses ("spec" when none).
  std::string basis() const;
  // The stages of this scene the envelope still bounds by the spec's rules, each with the reason
  // no measured rule replaces it (empty when every stage uses a measured rule): what a blind
  // envelope says in its case (issue 16, item 5: "say in the case when none can").
  std::string specStages() const;

 private:
  Interval storeFixedPoint(double lo, double hi) const;
  Interval storeFloat(double lo, double hi) const;

  const ref::CombinationTextures* textures_;
  const ref::PlaneFrame* frame_;
  ref::FramebufferFormat format_;
  std::vector<TextureEnvelope> lookups_;
  double threshold_;
  EnvelopePrecision pass_ = kEnvelopePass, warning_ = kEnvelopeQualityWarning;
  MeasuredArithmetic::Store store_ = MeasuredArithmetic::Store::Spec;
  bool floatThreshold_ = false;
  bool measuredAny_ = false;
  ref::TexelFormat texelFormat_;
};

}  // namespace voxref::emu
