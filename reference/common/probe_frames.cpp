#include "reference/common/probe_frames.h"

#include <bit>
#include <cmath>

namespace voxref::ref {
namespace {

std::uint32_t bitsOf(float v) { return std::bit_cast<std::uint32_t>(v); }

// Values packed four to a pixel (red, green, blue, alpha), rows of `width` pixels, padded with 0.
ProbeWrite packed(std::string_view id, FramebufferFormat format, int passes, const std::vector<float>& values) {
  constexpr int width = 64;
  const int pixels = static_cast<int>((values.size() + 3) / 4);
  ProbeWrite w{id, format, ProbeBlend::OneOne, width, (pixels + width - 1) / width, {}};
  std::vector<std::array<float, 4>> pass(static_cast<std::size_t>(w.width) * w.height, {0, 0, 0, 0});
  for (std::size_t i = 0; i < values.size(); ++i) pass[i / 4][i % 4] = values[i];
  w.passes.assign(static_cast<std::size_t>(passes), pass);
  return w;
}

// For every code k in `codes`: the float nearest (k + 1/2) / (2^b - 1) and its three neighbours on
// each side. Products fl(x (2^b - 1)) of these land on k + 1/2 exactly for most k (a tie of the
// float-to-unorm rounding) and just below and above it.
std::vector<float> halfwayValues(int bits, int codeStep) {
  const double maxCode = std::ldexp(1.0, bits) - 1.0;
  std::vector<float> out;
  for (int k = 0; k < static_cast<int>(maxCode); k += codeStep) {
    const float mid = static_cast<float>((k + 0.5) / maxCode);
    float lo = mid;
    for (int j = 0; j < 3; ++j) lo = std::nextafter(lo, 0.0f);
    for (int j = 0; j < 7; ++j, lo = std::nextafter(lo, 2.0f)) out.push_back(lo);
  }
  return out;
}

ProbeDesign makeDesign() {
  ProbeDesign d;
  constexpr int width = 128, height = ProbeDesign::kSamplesPerTexel / width + 1;  // 2^14 + 1 samples and a few more
  // Sample k sits k * 2^-14 texel past the first texel centre (u = 0.25 on a 2-texel texture).
  const float step2 = std::ldexp(1.0f, -15);
  d.sweeps.push_back(
      {"sweep.rgba8", true, Wrap::ClampToEdge, 2, {{0, 255, 10, 200}, {255, 0, 201, 3}}, 0.25f, step2, width, height});
  const float denormLo = std::ldexp(1.0f, -140), denormHi = std::ldexp(1.0f, -130);
  d.sweeps.push_back({"sweep.rgba32f",
                      false,
                      Wrap::ClampToEdge,
                      2,
                      {{bitsOf(0.0f), bitsOf(0.1f), bitsOf(denormLo), bitsOf(0.7f)},
                       {bitsOf(1.0f), bitsOf(1.7f), bitsOf(denormHi), bitsOf(-1.3f)}},
                      0.25f,
                      step2,
                      width,
                      height});
  // fract(u) = 0.25 + k 2^-21: between texel 0 and texel 1 of 3 for every sample of the target.
  d.sweeps.push_back({"sweep.repeat_npot",
                      false,
                      Wrap::Repeat,
                      3,
                      {{bitsOf(0.0f), 0, 0, 0}, {bitsOf(1.0f), 0, 0, 0}, {bitsOf(0.0f), 0, 0, 0}},
                      7.25f,
                      std::ldexp(1.0f, -21),
                      width,
                      height});

  d.writes.push_back(packed("store.rgba8", FramebufferFormat::RGBA8, 1, halfwayValues(8, 1)));
  d.writes.push_back(packed("store.rgba16", FramebufferFormat::RGBA16, 1, halfwayValues(16, 37)));
  std::vector<float> requantize;
  for (int k = 0; k < 128; ++k)
    for (double f : {0.2, 0.3, 0.7, 0.8}) requantize.push_back(static_cast<float>((k + f) / 255.0));
  d.writes.push_back(packed("requantize.rgba8", FramebufferFormat::RGBA8, 2, requantize));

  ProbeWrite blend{"blend.rgba8", FramebufferFormat::RGBA8, ProbeBlend::SrcAlpha, 256, 256, {}};
  auto unorm8 = [](int k) { return static_cast<float>(k) * (1.0f / 255.0f); };  // k * fl(1/255): what a texel reads as
  std::vector<std::array<float, 4>> dst, src;
  for (int a = 0; a < 256; ++a)
    for (int s = 0; s < 256; ++s) {
      dst.push_back({unorm8((s * 7 + a * 13 + 5) & 255), unorm8((s * 3 + a * 11) & 255), unorm8(s ^ a), 1.0f});
      src.push_back({unorm8(s), unorm8(255 - s), unorm8((s * 5 + a * 3) & 255), unorm8(a)});
    }
  blend.passes = {dst, src};
  d.writes.push_back(std::move(blend));
  return d;
}

}  // namespace

const ProbeDesign& probeDesign() {
  static const ProbeDesign design = makeDesign();
  return design;
}

}  // namespace voxref::ref
