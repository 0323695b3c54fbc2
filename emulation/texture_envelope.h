// The envelope: what ANY conforming GL implementation may return for a texture lookup, as an
// interval (the spec model of docs/design.md, after Khronos dEQP tcuTexLookupVerifier.cpp).
//
// Precision model (every number has its source):
//  - the shader computes the coordinate u = (p 2^l + 0.5) / D; GLSL 4.60 section 4.7.1 allows
//    2.5 ULP for the division (p 2^l + 0.5 is exact on voxref's lattice);
//  - the texture unit represents u with `coordBits` accurate float bits (dEQP:
//    computeFloatingPointError; 20 bits is dEQP's value for 3D textures);
//  - texel-space positions u N carry `uvwBits` fixed-point subtexel bits (dEQP:
//    computeFixedPointError; 7 for a pass, 4 for a quality warning, as dEQP retries);
//  - LINEAR: any texel cell and weights in the resulting ranges, the trilinear combination of
//    the exact texel values evaluated exactly (its extremes over a weight box lie at the box's
//    corners: the function is multilinear); NEAREST: any texel in the coordinate range;
//  - wrap modes index the texels as the GL specification says (section 8.14.2).
// Results are real intervals in double; bounds are rounded outward by 2^-40 relative so that the
// double evaluation never narrows them.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "reference/common/gl_state.h"
#include "reference/common/volume.h"

namespace voxref::emu {

struct Interval {
  double lo = 0.0, hi = 0.0;
  bool contains(double v) const { return v >= lo && v <= hi; }
};

struct EnvelopePrecision {
  int coordBits = 20;
  int uvwBits = 7;
  double divisionUlps = 2.5;
};
inline constexpr EnvelopePrecision kEnvelopePass{20, 7, 2.5};
inline constexpr EnvelopePrecision kEnvelopeQualityWarning{20, 4, 2.5};

// dEQP's computeFloatingPointError(value, bits): the error of a float with `bits` accurate
// mantissa bits at `value`'s exponent, and computeFixedPointError(bits).
double floatingPointError(double value, int accurateBits);
double fixedPointError(int accurateBits);

class TextureEnvelope {
 public:
  // `codes` must outlive the envelope; values are decoded exactly (texel_format.h).
  TextureEnvelope(const ref::Dims3& dims, ref::TexelFormat format, const std::vector<std::uint32_t>& codes,
                  const ref::SamplerState& sampler);
  // The values texture(sampler3D, u).r may take when the shader's exact coordinate is `uExact`
  // (before the shader's own rounding), under `precision`.
  Interval lookup(const glm::dvec3& uExact, const EnvelopePrecision& precision) const;

 private:
  struct Candidate {
    int i0;
    double wlo, whi;
  };
  int candidates(double u, int n, const EnvelopePrecision& precision, Candidate out[4]) const;
  double texel(int x, int y, int z) const;

  ref::Dims3 dims_;
  ref::SamplerState sampler_;
  std::vector<double> values_;
  double border_;
};

}  // namespace voxref::emu
