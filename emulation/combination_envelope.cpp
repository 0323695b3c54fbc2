#include "emulation/combination_envelope.h"

#include <algorithm>
#include <cmath>

#include "reference/common/frame_sampling.h"
#include "reference/common/rounding.h"
#include "reference/common/texel_format.h"

namespace voxref::emu {
namespace {

int colourBits(ref::FramebufferFormat f) {
  switch (f) {
    case ref::FramebufferFormat::RGBA16F:
      return 10;
    case ref::FramebufferFormat::RGBA32F:
      return 23;
    default:
      return ref::unormBits(f);
  }
}

int colourBits(ref::TexelFormat f) {
  switch (f) {
    case ref::TexelFormat::R16F:
      return 10;
    case ref::TexelFormat::R32F:
      return 23;
    default:
      return ref::unormBits(f);
  }
}

// The largest binary16 value <= x, and the smallest >= x.
double halfDown(double x) {
  const std::uint16_t h = ref::halfFromDouble(x);
  const double r = ref::halfToDouble(h);
  if (r <= x) return r;
  if (h == 0x0000u) return ref::halfToDouble(0x8001u);  // below +0: the negative subnormal
  return ref::halfToDouble(static_cast<std::uint16_t>(h & 0x8000u ? h + 1 : h - 1));
}
double halfUp(double x) { return -halfDown(-x); }

}  // namespace

CombinationEnvelope::CombinationEnvelope(const ref::CombinationTextures& textures, const ref::PlaneFrame& frame,
                                         const ref::SamplerState& sampler, ref::FramebufferFormat format,
                                         const MeasuredArithmetic& measured)
    : textures_(&textures),
      frame_(&frame),
      format_(format),
      measuredAny_(measured.any()),
      texelFormat_(textures.format) {
  for (const ref::GridTexture& t : textures.textures) lookups_.emplace_back(t.dims, textures.format, t.codes, sampler);
  const int bits = std::min(colourBits(format), colourBits(textures.format));
  threshold_ = std::ldexp(1.0, -(bits - (sampler.filter == ref::Filter::Linear ? 2 : 1)));
  if (ref::clampsToUnitRange(format) && ref::unormBits(format) == 8) store_ = measured.unorm8Store;
  floatThreshold_ = measured.floatFiltering && ref::unormBits(textures.format) != 8;
  if (floatThreshold_) {
    double largest = 1.0;
    int extent = 1;
    for (const ref::GridTexture& t : textures.textures) {
      for (std::uint32_t c : t.codes) largest = std::max(largest, std::fabs(ref::decodeTexel(textures.format, c)));
      for (int a = 0; a < 3; ++a) extent = std::max(extent, t.dims[a]);
    }
    threshold_ = ref::scaleByPowerOfTwo(largest, -20);
    const int uvw = std::max(kEnvelopePass.uvwBits, 24 - static_cast<int>(std::ceil(std::log2(extent))));
    pass_.uvwBits = std::min(uvw, 20);
    warning_.uvwBits = pass_.uvwBits - 3;
  }
}

std::string CombinationEnvelope::basis() const {
  std::string s;
  if (floatThreshold_) s = "measured float filtering";
  if (store_ == MeasuredArithmetic::Store::Nearest)
    s += std::string(s.empty() ? "" : ", ") + "measured nearest 8-bit stores";
  if (store_ == MeasuredArithmetic::Store::Floor)
    s += std::string(s.empty() ? "" : ", ") + "measured floor 8-bit stores";
  return s.empty() ? "spec" : s;
}

std::string CombinationEnvelope::specStages() const {
  if (!measuredAny_)
    return "every stage at the spec's rules: no measured arithmetic (--profile measured-envelope derives it from the "
           "probe)";
  std::string s;
  const auto add = [&s](const std::string& stage) { s += (s.empty() ? "" : "; ") + stage; };
  if (!floatThreshold_)
    add(ref::unormBits(texelFormat_) == 8
            ? "the lookup of an 8-bit texture (the probe measures float filtering, not how a driver filters unorm8)"
            : "the lookup (the probe did not determine float filtering)");
  if (ref::clampsToUnitRange(format_) && store_ == MeasuredArithmetic::Store::Spec)
    add(ref::unormBits(format_) == 8
            ? "the 8-bit store (the probe did not determine a per-pass rounding)"
            : "the " + std::to_string(ref::unormBits(format_)) + "-bit store (the probe measures 8-bit stores only)");
  if (!ref::clampsToUnitRange(format_)) add("the float blend (the probe does not measure float blend rounding)");
  return s;
}

Interval CombinationEnvelope::storeFixedPoint(double lo, double hi) const {
  const double m = ref::powerOfTwo(ref::unormBits(format_)) - 1.0;
  lo = std::clamp(lo, 0.0, 1.0);
  hi = std::clamp(hi, 0.0, 1.0);
  const double slack = ref::powerOfTwo(-16);  // codes: the float product x m is within 2^-24 relative
  if (store_ == MeasuredArithmetic::Store::Nearest)
    return {std::max(0.0, std::ceil(lo * m - 0.5 - slack)) / m, std::min(m, std::floor(hi * m + 0.5 + slack)) / m};
  if (store_ == MeasuredArithmetic::Store::Floor)
    return {std::max(0.0, std::floor(lo * m - slack)) / m, std::min(m, std::floor(hi * m + slack)) / m};
  // Either neighbouring code: floor and ceil, outward by 2^-40 against double rounding.
  const double clo = std::max(0.0, std::floor(lo * m * (1.0 - ref::powerOfTwo(-40))));
  const double chi = std::min(m, std::ceil(hi * m * (1.0 + ref::powerOfTwo(-40))));
  return {clo / m, chi / m};
}

Interval CombinationEnvelope::storeFloat(double lo, double hi) const {
  if (format_ == ref::FramebufferFormat::RGBA16F) return {halfDown(lo), halfUp(hi)};
  const double flo = static_cast<float>(lo), fhi = static_cast<float>(hi);
  return {flo <= lo ? flo : std::nextafter(static_cast<float>(lo), -INFINITY),
          fhi >= hi ? fhi : std::nextafter(static_cast<float>(hi), INFINITY)};
}

Interval CombinationEnvelope::at(int i, int j, int k, const EnvelopePrecision& precision) const {
  const glm::dvec3 p = frame_->sample(i, j, k);
  if (!ref::insideUnitCube(p)) return {0.0, 0.0};  // discarded: the cleared value
  const bool fixedPoint = ref::clampsToUnitRange(format_);
  Interval dst{0.0, 0.0};
  for (const ref::CombinationPass& pass : textures_->passes) {
    const ref::GridTexture& t = textures_->textures[pass.texture];
    if (!ref::servesCell(t, ref::scaleByPowerOfTwo(p.x, t.levels[0]), ref::scaleByPowerOfTwo(p.y, t.levels[1]),
                         ref::scaleByPowerOfTwo(p.z, t.levels[2])))
      continue;
    const glm::dvec3 u{ref::textureCoordinate(p.x, t.levels[0], t.dims[0], t.origin[0]),
                       ref::textureCoordinate(p.y, t.levels[1], t.dims[1], t.origin[1]),
                       ref::textureCoordinate(p.z, t.levels[2], t.dims[2], t.origin[2])};
    Interval src = lookups_[pass.texture].lookup(u, precision);
    src.lo -= threshold_;
    src.hi += threshold_;
    if (fixedPoint) {
      src.lo = std::clamp(src.lo, 0.0, 1.0);
      src.hi = std::clamp(src.hi, 0.0, 1.0);
    }
    const bool add = pass.equation == ref::BlendEquation::FuncAdd;
    const double lo = add ? dst.lo + src.lo : dst.lo - src.hi;
    const double hi = add ? dst.hi + src.hi : dst.hi - src.lo;
    const double pad = ref::scaleByPowerOfTwo(std::max(std::fabs(lo), std::fabs(hi)), -40);
    dst = fixedPoint ? storeFixedPoint(lo - pad, hi + pad) : storeFloat(lo - pad, hi + pad);
  }
  return dst;
}

}  // namespace voxref::emu
