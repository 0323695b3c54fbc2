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
#pragma once

#include <vector>

#include "emulation/texture_envelope.h"
#include "reference/common/plane_frame.h"
#include "reference/sparsegrid/combination_textures.h"

namespace voxref::emu {

class CombinationEnvelope {
 public:
  CombinationEnvelope(const ref::CombinationTextures& textures, const ref::PlaneFrame& frame,
                      const ref::SamplerState& sampler, ref::FramebufferFormat format);
  // The stored values (decoded exactly, framebuffer_codes.h) allowed at sample (i, j, k).
  Interval at(int i, int j, int k, const EnvelopePrecision& precision) const;
  // The colour threshold applied to every pass's source value, and its derivation.
  double colourThreshold() const { return threshold_; }

 private:
  Interval storeFixedPoint(double lo, double hi) const;
  Interval storeFloat(double lo, double hi) const;

  const ref::CombinationTextures* textures_;
  const ref::PlaneFrame* frame_;
  ref::FramebufferFormat format_;
  std::vector<TextureEnvelope> lookups_;
  double threshold_;
};

}  // namespace voxref::emu
