// The envelope of the time-varying decoders (Binotto et al. 2003; reference/timevarying/
// decoder_variants.h): the RGBA8 values ANY conforming GL implementation may read back for a
// sample, decoded by the shaders of gpu/shaders/timevarying_*.frag, alone (decode planes) or
// composited back to front with SRC_ALPHA / ONE_MINUS_SRC_ALPHA into RGBA8. The dEQP-style model of
// docs/design.md ("envelope"), after tcuTexLookupVerifier.cpp; every rule has its source:
//
//  - shader arithmetic: interval arithmetic of interval_arithmetic.h (GLSL 4.60 section 4.7.1):
//    + - * correctly rounded, division 2.5 ULP (`divisionUlps`), mod(x, y) = x - y floor(x / y)
//    with a branch per integer floor may give (both sides of a cell face), floor exact, int()
//    truncating (GLSL 4.60 section 5.4.1). The sample point is exact: samplePoint() is exact in
//    float32 on voxref's lattice under any rounding (plane_frame.h). Uniforms are the exact values
//    gpu/timevarying_gl.cpp sets;
//  - NEAREST lookups (GL 4.6 section 8.14.2, CLAMP_TO_EDGE): the coordinate interval widened by
//    dEQP's coordinate error (`coordBits` accurate float bits, computeFloatingPointError) and
//    subtexel error (`uvwBits`, computeFixedPointError), as computeNonNormalizedCoordBounds does;
//    every texel whose cell that range touches may be read;
//  - texel values: unorm codes converted as unormToFloatF32 (GL 4.6 section 2.3.5.1, 2.5 ULP, exact
//    at 0 and 1; both tiers use kEnvelopePass.divisionUlps for it), float texels exact or flushed to zero when denormal
//    (GLSL 4.60 section 4.7.1);
//  - texelFetch outside the texture: undefined (GL 4.6 section 11.1.3.2): any value; mod(x, 0)
//    (the literal decoder): the quotient is unconstrained (division precision is given only for
//    |b| >= 2^-126), so its refinement lookup may read any texel;
//  - `c.a == 1.0` is decided exactly: unorm alpha converts to exactly 1.0 only from the maximum code;
//  - fragment output to RGBA8: clamp, then either of the two closest codes (GL 4.6 section 2.3.5.2);
//  - blending (GL 4.6 section 17.3.6): source, alpha and destination clamped to [0, 1]; the blend
//    "as if in floating point" with "a precision no lower than" the destination's: every operation
//    (the source and alpha values, s a, 1 - a, d (1 - a), the sum) may round its exact result to
//    either neighbouring 8-bit level, the sum is clamped and stored (2.3.5.2). An exact result on
//    a level stays there (float32 blenders' rounding of ~2^-24 relative is not modelled; it can
//    move a value only across a level it sits on, which RNE-storing drivers never do).
//  - with arithmetic the probe measured (measured_arithmetic.h, docs/oracles.md): a composite's
//    fragment colour is stored to the nearest code (store.unorm8_rounding), and each blend is the
//    measured integer formula min(255, m(s, a) + m(d, 255 - a)) (blend.rgba8_src_alpha), exact on
//    the code intervals: m is monotone in each argument, so the extremes lie at the ends of s and
//    d and at some a of its interval, which is enumerated.
//
// Where several texels or branches are possible, a decoded sample allows the UNION of their colours
// (boxes of RGBA codes, one per candidate: a colour must fit one candidate in all four channels).
// Composites propagate the per-channel interval HULL of the candidates through the blend (the
// channels of one candidate are not kept together there): sound, not tight. Composited envelopes
// widen with every translucent slice; their width is a figure of the spec, not of a driver.
//
// Inputs: textures as ref::encodeTimeVarying makes them; frames on voxref's float32 lattice.
// Outputs: integer code intervals. Deterministic for every thread count. Throws
// std::invalid_argument when the decoder cannot read these textures (as TimeVaryingDecoderEmu).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "emulation/measured_arithmetic.h"
#include "emulation/texture_envelope.h"
#include "reference/common/plane_frame.h"
#include "reference/common/rgba.h"
#include "reference/timevarying/decoder_variants.h"

namespace voxref::emu {

using RgbaIntervals = std::array<Interval, 4>;

// A union of boxes of RGBA8 codes (integer intervals per channel).
struct AllowedColours {
  std::vector<RgbaIntervals> boxes;
  bool contains(const ref::Rgba8& c) const;
  // How far `c` lies outside: over the boxes, the smallest largest-channel distance in codes (0 when
  // contained); `box` is that nearest box, `channel` the channel that misses most in it, `allowed`
  // its interval there.
  struct Miss {
    int codes = 0;
    int channel = 0;
    Interval allowed;
    std::size_t box = 0;
  };
  Miss miss(const ref::Rgba8& c) const;
  RgbaIntervals hull() const;
};

class TimeVaryingEnvelope {
 public:
  TimeVaryingEnvelope(const ref::TimeVaryingTextures& textures, ref::DecoderVariant variant,
                      const MeasuredArithmetic& measured = {});
  // Which measured rules the composites use ("spec" when none).
  std::string basis() const;

  // The fragment colours (float intervals per channel, one entry per candidate decode) the shader may
  // write at sample point p of `step`; `discarded` when p is outside the unit cube.
  struct Fragment {
    bool discarded = false;
    std::vector<RgbaIntervals> colours;
  };
  void fragment(int step, const glm::dvec3& p, const EnvelopePrecision& precision, Fragment& out) const;

  // The RGBA8 codes a decode-only read-back may hold at p ({0, 0, 0, 0} where discarded).
  AllowedColours decoded(int step, const glm::dvec3& p, const EnvelopePrecision& precision) const;
  // The RGBA8 codes of pixel (i, j) after the frame's planes are composited back to front
  // (k = planes - 1 first) into a target cleared to 0: one box (the per-channel hull).
  AllowedColours composited(int step, const ref::PlaneFrame& frame, int i, int j,
                            const EnvelopePrecision& precision) const;

 private:
  struct Range {
    int lo, hi;
  };
  RgbaIntervals indexValue(int x, int y, int z) const;
  RgbaIntervals refinementValue(int x, int y, int z) const;
  Range nearest(const Interval& s, int n, const EnvelopePrecision& precision) const;
  void addRefinement(const std::array<std::vector<Range>, 3>& axes, std::vector<RgbaIntervals>& out) const;
  void paperOrLiteral(int step, const glm::dvec3& p, const EnvelopePrecision& precision,
                      std::vector<RgbaIntervals>& out) const;
  void texelCentre(int step, const glm::dvec3& p, const EnvelopePrecision& precision,
                   std::vector<RgbaIntervals>& out) const;
  void texelFetch(int step, const glm::dvec3& p, std::vector<RgbaIntervals>& out) const;

  const ref::TimeVaryingTextures* tex_;
  ref::DecoderVariant variant_;
  RgbaIntervals refinementHull_{};  // every refinement texel: what an unconstrained lookup may read
  MeasuredArithmetic measured_;
};

// Per sample of a read-back (`judged`, as emulateDecodePlanes or emulateComposite lay it out): 0
// inside the pass envelope (kEnvelopePass), 1 only inside the quality-warning envelope
// (kEnvelopeQualityWarning), 2 outside both. `widths`, when given, receives per sample the widest
// channel of the pass envelope's hull, in codes (0: a single colour allowed).
std::vector<std::uint8_t> envelopeTiers(const TimeVaryingEnvelope& envelope, int step, const ref::PlaneFrame& frame,
                                        bool composite, const ref::RgbaStack& judged, int threads = 0,
                                        std::vector<std::uint8_t>* widths = nullptr);

}  // namespace voxref::emu
