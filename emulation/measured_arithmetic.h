// What the probe measured of a driver's arithmetic that an envelope may rely on instead of the
// spec's allowance (docs/oracles.md, "Envelopes from measured arithmetic"), as dEQP relies on an
// implementation's declared precision bits. Only properties the probe determined (never
// "unknown") are set; every unset one leaves the spec's rule in place.
#pragma once

#include <string>

namespace voxref::emu {

struct MeasuredArithmetic {
  // sampling.float.subtexel_bits = float and sampling.float.lerp fused or unfused: LINEAR lookups
  // of non-unorm8 textures weight their texels with float weights from the float u N, and lerp in
  // float32. Measured on RGBA32F only: for unorm16 and half-float textures an assumption
  // (docs/oracles.md), which is why a run relies on it only when asked to (measured-envelope).
  bool floatFiltering = false;
  // store.unorm8_rounding: an 8-bit store rounds to nearest (half_even or half_up: `Nearest`) or
  // down (`Floor`) instead of to either neighbouring code (GL 4.6 section 2.3.5.2).
  enum class Store { Spec, Nearest, Floor } unorm8Store = Store::Spec;
  // framebuffer.between_passes = requantized: every pass's blend reads the stored 8-bit code.
  bool requantizedPasses = false;
  // blend.rgba8_src_alpha with requantized passes: SRC_ALPHA / ONE_MINUS_SRC_ALPHA on codes,
  // min(255, m(s, a) + m(d, 255 - a)) with m = Mesa's mulnorm (lp_build_mul_norm) or the exact
  // round(x y / 255); `Spec` where it is float or unknown.
  enum class Blend { Spec, Mulnorm, Exact } srcAlphaBlend = Blend::Spec;

  bool any() const { return floatFiltering || unorm8Store != Store::Spec || srcAlphaBlend != Blend::Spec; }
  // The properties relied on, as "id = value" phrases, for the report.
  std::string describe() const;
};

// From the probed properties' values by id (conformance/framework/probe/driver_fingerprint.h);
// `value(id)` is empty for a property the probe did not report.
template <class Lookup>
MeasuredArithmetic measuredArithmetic(Lookup&& value) {
  MeasuredArithmetic m;
  const std::string lerp = value("sampling.float.lerp");
  m.floatFiltering = value("sampling.float.subtexel_bits") == "float" && (lerp == "fused" || lerp == "unfused");
  m.requantizedPasses = value("framebuffer.between_passes") == "requantized";
  // A per-pass store rule means something only where every pass is stored.
  const std::string store = value("store.unorm8_rounding");
  if (m.requantizedPasses && (store == "half_even" || store == "half_up"))
    m.unorm8Store = MeasuredArithmetic::Store::Nearest;
  if (m.requantizedPasses && store == "floor") m.unorm8Store = MeasuredArithmetic::Store::Floor;
  const std::string blend = value("blend.rgba8_src_alpha");
  if (m.requantizedPasses && blend == "mulnorm") m.srcAlphaBlend = MeasuredArithmetic::Blend::Mulnorm;
  if (m.requantizedPasses && blend == "exact") m.srcAlphaBlend = MeasuredArithmetic::Blend::Exact;
  return m;
}

}  // namespace voxref::emu
