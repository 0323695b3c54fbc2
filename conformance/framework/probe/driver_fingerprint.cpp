#include "conformance/framework/probe/driver_fingerprint.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <map>
#include <stdexcept>

#include "emulation/float32.h"
#include "emulation/framebuffer_emu.h"

// The candidate formulas below are float32 arithmetic: this file is compiled with
// -ffp-contract=off (conformance/CMakeLists.txt), so every operation rounds once, and the one
// fused candidate calls std::fma.
namespace voxref::conf {
namespace {

using ref::ProbeDesign;
using ref::ProbeFrame;
constexpr int kTexel = ProbeDesign::kSamplesPerTexel;  // sweep samples from one texel centre to the next

std::string str(std::size_t n) { return std::to_string(n); }

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

float valueOf(std::uint32_t bits) { return std::bit_cast<float>(bits); }

const ProbeFrame& frameOf(std::span<const ProbeFrame> frames, std::string_view id, ref::FramebufferFormat format,
                          int width, int height) {
  for (const ProbeFrame& f : frames)
    if (f.id == id) {
      if (f.format != format || f.width != width || f.height != height ||
          f.codes.size() != static_cast<std::size_t>(width) * height)
        throw std::invalid_argument("probe frame " + std::string(id) + " does not have the design's format and size");
      return f;
    }
  throw std::invalid_argument("probe frame " + std::string(id) + " is missing");
}

const ref::ProbeSweep& sweepOf(const ProbeDesign& d, std::string_view id) {
  for (const auto& s : d.sweeps)
    if (s.id == id) return s;
  throw std::logic_error("probe design has no sweep " + std::string(id));
}

const ref::ProbeWrite& writeOf(const ProbeDesign& d, std::string_view id) {
  for (const auto& w : d.writes)
    if (w.id == id) return w;
  throw std::logic_error("probe design has no write " + std::string(id));
}

// --- Sweeps: weights, coordinate rounding, lerps ---------------------------------------------

// Samples k in 1..kTexel whose RGBA differs from sample k - 1's: the steps of the filtered result
// across one texel. With four channels whose texel pairs differ in sign and size, two adjacent
// weights never give the same RGBA on the probe's textures.
std::vector<int> stepsAcrossTexel(const ProbeFrame& f) {
  std::vector<int> at;
  for (int k = 1; k <= kTexel; ++k)
    if (f.codes[k] != f.codes[k - 1]) at.push_back(k);
  return at;
}

// n for 2^n steps; -1 when every sample differs (weights finer than the probe resolves); -2 otherwise.
constexpr int kFloatWeights = -1, kOddSteps = -2;
int weightBits(std::size_t steps) {
  if (steps == static_cast<std::size_t>(kTexel)) return kFloatWeights;
  if (steps >= 2 && std::has_single_bit(steps)) return std::countr_zero(steps);
  return kOddSteps;
}

InferredProperty subtexelBits(std::string id, std::size_t steps) {
  const int bits = weightBits(steps);
  const std::string across = " across one texel (" + str(kTexel + 1) + " samples 2^-14 texel apart)";
  if (bits == kFloatWeights)
    return {id, "float",
            "the result changes at every one of the " + str(steps) + " samples" + across +
                ": weights finer than 2^-14 texel, not fixed point"};
  if (bits == kOddSteps)
    return {id, "unknown", "the result changes " + str(steps) + " times" + across + ": not a power of two"};
  return {id, std::to_string(bits),
          "the result changes " + str(steps) + " times" + across + ", in runs of " + str(kTexel / steps) +
              " samples: 2^" + std::to_string(bits) + " weights"};
}

// Where the steps fall on the fixed-point grid of n bits. Step j (to weight m = j + 1) at sample k
// lies at offset k - (m S - S/2) from the half-way point between weights m - 1 and m (S samples
// per weight): 0 for ties rounded up, 1 for ties rounded down, S/2 for floor.
InferredProperty coordinateRounding(const std::vector<int>& steps, int bits) {
  const std::string id = "sampling.unorm8.coordinate_rounding";
  if (bits == kFloatWeights) return {id, "float", "weights are not fixed point (see subtexel_bits)"};
  if (bits < 0) return {id, "unknown", "no fixed-point grid: the weight count is not a power of two"};
  const int perWeight = kTexel >> bits;
  std::map<std::string, std::function<int(int)>> candidates{
      {"half_up", [](int) { return 0; }},
      {"half_down", [](int) { return 1; }},
      {"half_even", [](int m) { return m % 2 ? 1 : 0; }},
      {"floor", [perWeight](int) { return perWeight / 2; }},
  };
  std::size_t evenAtHalf = 0, oddAfterHalf = 0;
  std::map<std::string, std::size_t> fits;
  for (std::size_t j = 0; j < steps.size(); ++j) {
    const int m = static_cast<int>(j) + 1;
    const int offset = steps[j] - (m * perWeight - perWeight / 2);
    for (const auto& [name, expected] : candidates) fits[name] += offset == expected(m) ? 1 : 0;
    evenAtHalf += m % 2 == 0 && offset == 0;
    oddAfterHalf += m % 2 == 1 && offset == 1;
  }
  std::string value = "unknown";
  for (const auto& [name, n] : fits)
    if (n == steps.size()) value = name;
  std::string evidence = "of " + str(steps.size()) + " steps, " + str(evenAtHalf) +
                         " to an even weight fall on the half-way sample and " + str(oddAfterHalf) +
                         " to an odd weight one sample (2^-14 texel) after it; fits:";
  for (const auto& [name, n] : fits) evidence += " " + name + " " + str(n);
  return {id, value, evidence};
}

// The unorm8 code a float stands for when it is one (k * fl(1/255)), else -1.
int unorm8CodeOf(float v) {
  if (!(v >= 0.0f && v <= 1.0f)) return -1;
  const auto k = static_cast<std::uint32_t>(std::nearbyint(v * 255.0f));
  return emu::unormToFloat(k, 8) == v ? static_cast<int>(k) : -1;
}

InferredProperty lerp8Rounding(const ProbeFrame& f, const ref::ProbeSweep& sweep, const std::vector<int>& steps,
                               int bits) {
  const std::string id = "sampling.unorm8.lerp_rounding";
  std::size_t between = 0;
  for (int k = 0; k <= kTexel; ++k)
    for (int c = 0; c < 4; ++c) between += unorm8CodeOf(valueOf(f.codes[k][c])) < 0;
  if (between)
    return {id, "float",
            str(between) + " of " + str(4 * (kTexel + 1)) + " results lie between unorm8 codes: the lerp is not 8-bit"};
  if (bits < 0) return {id, "unknown", "8-bit results, but no fixed-point weight grid to hold them against"};
  // Weight w of run w (the samples before step w + 1); the run after the last step is texel 1.
  const int one = 1 << bits;
  std::size_t nearest = 0, floor = 0, pairs = 0, differ = 0;
  for (int w = 0; w < one; ++w) {
    const int k = w == 0 ? 0 : steps[w - 1];
    for (int c = 0; c < 4; ++c) {
      const int a = static_cast<int>(sweep.texelCodes[0][c]), b = static_cast<int>(sweep.texelCodes[1][c]);
      const int got = unorm8CodeOf(valueOf(f.codes[k][c]));
      const int n = a + ((w * (b - a) + one / 2) >> bits), fl = a + ((w * (b - a)) >> bits);  // >>: floor
      ++pairs;
      differ += n != fl;
      nearest += got == n;
      floor += got == fl;
    }
  }
  const std::string value = nearest == pairs && floor < pairs   ? "nearest"
                            : floor == pairs && nearest < pairs ? "floor"
                                                                : "unknown";
  return {id, value,
          str(one) + " weights x 4 channels (" + str(differ) + " where the candidates differ): a + ((w(b-a) + " +
              str(one / 2) + ") >> " + std::to_string(bits) + ") fits " + str(nearest) + ", a + (w(b-a) >> " +
              std::to_string(bits) + ") fits " + str(floor)};
}

InferredProperty floatLerp(const ProbeFrame& f, const ref::ProbeSweep& sweep) {
  std::size_t differ = 0, fused = 0, unfused = 0;
  for (int k = 0; k <= kTexel; ++k) {
    const float w = valueOf(f.codes[k][0]);  // red: texels 0 and 1, the weight itself
    for (int c : {1, 3}) {
      const float a = valueOf(sweep.texelCodes[0][c]), b = valueOf(sweep.texelCodes[1][c]);
      const float d = b - a;
      const float fu = std::fma(w, d, a), un = a + w * d;
      if (fu == un) continue;
      ++differ;
      const float got = valueOf(f.codes[k][c]);
      fused += got == fu;
      unfused += got == un;
    }
  }
  const std::string value = differ && fused == differ ? "fused" : differ && unfused == differ ? "unfused" : "unknown";
  return {"sampling.float.lerp", value,
          "of " + str(differ) +
              " samples where fma(w, b-a, a) and a + fl(w(b-a)) differ (w read from the 0 -> 1 channel), fused fits " +
              str(fused) + ", unfused " + str(unfused)};
}

InferredProperty denormals(const ProbeFrame& f, const ref::ProbeSweep& sweep) {
  std::size_t zero = 0, lerped = 0;
  const float a = valueOf(sweep.texelCodes[0][2]), b = valueOf(sweep.texelCodes[1][2]);
  for (int k = 0; k <= kTexel; ++k) {
    const float w = valueOf(f.codes[k][0]), got = valueOf(f.codes[k][2]);
    zero += got == 0.0f;
    lerped += got != 0.0f && (got == std::fma(w, b - a, a) || got == a + w * (b - a));
  }
  const std::size_t n = kTexel + 1;
  const std::string value = zero == n ? "flushed" : lerped == n ? "kept" : "unknown";
  return {"sampling.float.denormals", value,
          "texels 2^-140 and 2^-130 filtered at " + str(n) + " samples: " + str(zero) + " read back 0, " + str(lerped) +
              " the denormal lerp"};
}

// The finest power of two dividing every weight of the REPEAT sweep, against the float spacing of
// u * N: a weight computed from fl(u N) cannot be finer than that spacing; one from fract(u) * N is.
InferredProperty repeatScaling(const ProbeFrame& f, const ref::ProbeSweep& sweep) {
  const std::string id = "sampling.float.repeat_scaling";
  int finest = 1000;
  const std::size_t n = f.codes.size();
  for (std::size_t k = 0; k < n; ++k) {
    const float w = valueOf(f.codes[k][0]);
    if (!(w > 0.0f && w < 1.0f)) return {id, "unknown", "sample " + str(k) + " gives a weight outside (0, 1)"};
    const auto scaled =
        static_cast<std::uint64_t>(std::ldexp(static_cast<double>(w), 60));  // exact: w >= 2^-60 has <= 24 bits
    finest = std::min(finest, std::countr_zero(scaled) - 60);
  }
  const float uN = sweep.u(0) * static_cast<float>(sweep.texels);
  const int spacing = std::ilogb(uN) - 23;  // exponent of the float spacing at u N
  const std::string weights = "weights of " + str(n) + " samples at u = " + num(sweep.u(0)) + " + k 2^" +
                              std::to_string(std::ilogb(sweep.uStep)) + " on " + std::to_string(sweep.texels) +
                              " texels are multiples of 2^" + std::to_string(finest);
  const std::string of =
      "the float spacing 2^" + std::to_string(spacing) + " at u * " + std::to_string(sweep.texels) + " = " + num(uN);
  if (finest == spacing) return {id, "scale_then_floor", weights + ", " + of + ": u is scaled before it is wrapped"};
  if (finest < spacing)
    return {id, "fract_then_scale", weights + ", finer than " + of + ": u is wrapped (fract) before it is scaled"};
  return {id, "unknown", weights + ", coarser than " + of + ": weights quantized to fixed point"};
}

// --- Writes: unorm conversion, re-quantization, blending -------------------------------------

using Rounder = std::function<std::uint32_t(float, int)>;  // float in [0, 1] -> unorm code of b bits

const std::map<std::string, Rounder>& storeCandidates() {
  static const std::map<std::string, Rounder> c{
      {"half_even", [](float x, int b) { return emu::floatToUnormHalfEven(x, b); }},
      {"half_up", [](float x, int b) { return emu::floatToUnormHalfUp(x, b); }},
      {"floor",
       [](float x, int b) {
         const float p = std::clamp(x, 0.0f, 1.0f) * static_cast<float>((1u << b) - 1u);
         return static_cast<std::uint32_t>(p);
       }},
  };
  return c;
}

InferredProperty storeRounding(std::string id, const ProbeFrame& f, const ref::ProbeWrite& write, int bits) {
  const float maxCode = static_cast<float>((1u << bits) - 1u);
  std::size_t samples = 0, tiesEvenDown = 0, tiesOddUp = 0, ties = 0;
  std::map<std::string, std::size_t> fits;
  for (std::size_t i = 0; i < f.codes.size(); ++i)
    for (int c = 0; c < 4; ++c) {
      const float x = write.passes[0][i][c];
      const std::uint32_t got = f.codes[i][c];
      ++samples;
      for (const auto& [name, round] : storeCandidates()) fits[name] += round(x, bits) == got;
      const float p = x * maxCode;
      if (p - std::floor(p) != 0.5f) continue;
      ++ties;
      const auto k = static_cast<std::uint32_t>(p);
      tiesEvenDown += k % 2 == 0 && got == k;
      tiesOddUp += k % 2 == 1 && got == k + 1;
    }
  std::string value = "unknown";
  std::size_t allFit = 0;
  for (const auto& [name, n] : fits)
    if (n == samples) value = name, ++allFit;
  if (allFit > 1) value = "unknown";
  std::string evidence = str(ties) + " of " + str(samples) + " values are ties (fl(x * " +
                         std::to_string(static_cast<int>(maxCode)) + ") = k + 1/2): " + str(tiesEvenDown) +
                         " with k even went down, " + str(tiesOddUp) + " with k odd went up; fits:";
  for (const auto& [name, n] : fits) evidence += " " + name + " " + str(n);
  return {std::move(id), value, evidence};
}

InferredProperty betweenPasses(const ProbeFrame& f, const ref::ProbeWrite& write, const InferredProperty& unorm8) {
  const std::string id = "framebuffer.between_passes";
  const auto rounder = storeCandidates().find(unorm8.value);
  if (rounder == storeCandidates().end()) return {id, "unknown", "the unorm8 store rounding is unknown"};
  const Rounder& q = rounder->second;
  std::size_t differ = 0, perPass = 0, floatTile = 0;
  for (std::size_t i = 0; i < f.codes.size(); ++i)
    for (int c = 0; c < 4; ++c) {
      const float x = write.passes[0][i][c];  // the same x in both passes
      const std::uint32_t stored = std::min(2 * q(x, 8), 255u), kept = q(std::min(x + x, 1.0f), 8);
      if (stored == kept) continue;
      ++differ;
      perPass += f.codes[i][c] == stored;
      floatTile += f.codes[i][c] == kept;
    }
  const std::string value = differ && perPass == differ     ? "requantized"
                            : differ && floatTile == differ ? "float_tile_cache"
                                                            : "unknown";
  return {id, value,
          "two ONE/ONE passes of x into RGBA8, " + str(differ) + " values where the models differ: q(x) + q(x) fits " +
              str(perPass) + ", q(x + x) fits " + str(floatTile) + " (q: " + unorm8.value + ")"};
}

InferredProperty alphaBlend(const ProbeFrame& f, const ref::ProbeWrite& write, const InferredProperty& unorm8) {
  const std::string id = "blend.rgba8_src_alpha";
  const auto rounder = storeCandidates().find(unorm8.value);
  if (rounder == storeCandidates().end()) return {id, "unknown", "the unorm8 store rounding is unknown"};
  const Rounder& q = rounder->second;
  auto code = [](float v) {
    return static_cast<unsigned>(std::nearbyint(v * 255.0f));
  };  // the inputs are unorm8 floats
  std::size_t differ = 0, mul = 0, exact = 0, flt = 0;
  for (std::size_t i = 0; i < f.codes.size(); ++i) {
    const auto& dst = write.passes[0][i];  // (d, 1): stored as d by every candidate
    const auto& src = write.passes[1][i];
    const unsigned a = code(src[3]);
    for (int c = 0; c < 4; ++c) {
      const unsigned s = code(src[c]), d = code(dst[c]);
      const unsigned m =
          std::min(255u, unsigned{emu::mulnorm8(static_cast<std::uint8_t>(s), static_cast<std::uint8_t>(a))} +
                             emu::mulnorm8(static_cast<std::uint8_t>(d), static_cast<std::uint8_t>(255 - a)));
      const unsigned e = std::min(255u, (s * a + 127) / 255 + (d * (255 - a) + 127) / 255);
      const float A = emu::unormToFloat(a, 8);
      const float sum = emu::unormToFloat(s, 8) * A + emu::unormToFloat(d, 8) * (1.0f - A);
      const unsigned fl = q(std::min(sum, 1.0f), 8);
      if (m == e && e == fl) continue;
      ++differ;
      const std::uint32_t got = f.codes[i][c];
      mul += got == m;
      exact += got == e;
      flt += got == fl;
    }
  }
  const std::string value = differ && mul == differ     ? "mulnorm"
                            : differ && exact == differ ? "exact"
                            : differ && flt == differ   ? "float"
                                                        : "unknown";
  return {id, value,
          str(differ) + " channels where the candidates differ: (t + (t >> 8) + 128) >> 8 fits " + str(mul) +
              ", round(x y / 255) fits " + str(exact) + ", float32 blend rounded once fits " + str(flt)};
}

}  // namespace

const InferredProperty* DriverFingerprint::find(std::string_view id) const {
  for (const InferredProperty& p : properties)
    if (p.id == id) return &p;
  return nullptr;
}

DriverFingerprint inferFingerprint(const ProbeDesign& design, std::span<const ProbeFrame> frames) {
  using ref::FramebufferFormat;
  auto sweepFrame = [&](const ref::ProbeSweep& s) -> const ProbeFrame& {
    return frameOf(frames, s.id, FramebufferFormat::RGBA32F, s.width, s.height);
  };
  auto writeFrame = [&](const ref::ProbeWrite& w) -> const ProbeFrame& {
    return frameOf(frames, w.id, w.format, w.width, w.height);
  };
  DriverFingerprint fp;
  auto& out = fp.properties;

  const ref::ProbeSweep& s8 = sweepOf(design, "sweep.rgba8");
  const ProbeFrame& f8 = sweepFrame(s8);
  const std::vector<int> steps8 = stepsAcrossTexel(f8);
  out.push_back(subtexelBits("sampling.unorm8.subtexel_bits", steps8.size()));
  out.push_back(coordinateRounding(steps8, weightBits(steps8.size())));
  out.push_back(lerp8Rounding(f8, s8, steps8, weightBits(steps8.size())));

  const ref::ProbeSweep& s32 = sweepOf(design, "sweep.rgba32f");
  const ProbeFrame& f32 = sweepFrame(s32);
  out.push_back(subtexelBits("sampling.float.subtexel_bits", stepsAcrossTexel(f32).size()));
  out.push_back(floatLerp(f32, s32));
  const ref::ProbeSweep& repeat = sweepOf(design, "sweep.repeat_npot");
  out.push_back(repeatScaling(sweepFrame(repeat), repeat));
  out.push_back(denormals(f32, s32));

  const ref::ProbeWrite& st8 = writeOf(design, "store.rgba8");
  out.push_back(storeRounding("store.unorm8_rounding", writeFrame(st8), st8, 8));
  const ref::ProbeWrite& st16 = writeOf(design, "store.rgba16");
  out.push_back(storeRounding("store.unorm16_rounding", writeFrame(st16), st16, 16));
  const InferredProperty unorm8 = out[out.size() - 2];
  const ref::ProbeWrite& rq = writeOf(design, "requantize.rgba8");
  out.push_back(betweenPasses(writeFrame(rq), rq, unorm8));
  const ref::ProbeWrite& bl = writeOf(design, "blend.rgba8");
  out.push_back(alphaBlend(writeFrame(bl), bl, unorm8));
  return fp;
}

}  // namespace voxref::conf
