#include "emulation/timevarying_emu.h"

#include <bit>
#include <cmath>
#include <stdexcept>

#include "emulation/float32.h"
#include "emulation/framebuffer_emu.h"
#include "emulation/texture_sampler_emu.h"
#include "reference/common/parallel.h"

namespace voxref::emu {
namespace {

std::size_t texelOffset(const ref::Dims3& d, const std::array<int, 3>& t) {
  return static_cast<std::size_t>(t[0]) +
         static_cast<std::size_t>(d[0]) * (t[1] + static_cast<std::size_t>(d[1]) * t[2]);
}

bool inside(const ref::Dims3& d, const std::array<int, 3>& t) {
  return t[0] >= 0 && t[1] >= 0 && t[2] >= 0 && t[0] < d[0] && t[1] < d[1] && t[2] < d[2];
}

// float -> int as GLSL int() compiles on both drivers: truncation; NaN and out-of-range: INT_MIN.
int glslInt(float v) { return std::isnan(v) || std::fabs(v) >= 2147483648.0f ? INT32_MIN : static_cast<int>(v); }

ref::Rgba8 outputRgba8(const std::array<float, 4>& v) {
  ref::Rgba8 c{};
  for (int i = 0; i < 4; ++i) c[i] = static_cast<std::uint8_t>(floatToUnormHalfEven(v[i], 8));
  return c;
}

}  // namespace

TimeVaryingDecoderEmu::TimeVaryingDecoderEmu(const ref::TimeVaryingTextures& textures, ref::DecoderVariant variant,
                                             const PrecisionProfile& profile, bool forceAllEffects)
    : tex_(&textures), variant_(variant), profile_(&profile), force_(forceAllEffects) {
  if (const std::string why = ref::decoderIncompatibility(variant, textures.layout, textures.index.encoding);
      !why.empty())
    throw std::invalid_argument(why);
  if (force_) {  // LINEAR weights with CLAMP_TO_EDGE, the decoders' wrap
    const ref::SamplerState linear{ref::Filter::Linear, ref::Wrap::ClampToEdge, 0.0};
    indexWeights_.emplace(textures.index.dims, ref::TexelFormat::RGBA8, noCodes_, linear, profile);
    refinementWeights_.emplace(textures.refinement.dims, ref::TexelFormat::RGBA8, noCodes_, linear, profile);
  }
}

std::array<float, 4> TimeVaryingDecoderEmu::forcedWeights(const std::optional<TextureSamplerEmu>& w,
                                                          std::array<float, 4> v, const float c[3]) const {
  if (w)
    for (float& x : v) x = w->weightStageIdentity(x, c[0], c[1], c[2]);
  return v;
}

std::vector<Effect> TimeVaryingDecoderEmu::effects() const {
  std::vector<Effect> e;
  switch (tex_->index.encoding) {
    case ref::IndexEncoding::NormalizedRgba16:
      e.push_back(Effect::TexelUnorm16);
      break;
    case ref::IndexEncoding::NormalizedFloat:
      e.push_back(Effect::TexelFloat32);
      break;
    default:
      e.push_back(Effect::TexelUnorm8);
  }
  e.push_back(Effect::UnormToFloatReciprocal);
  auto add = [&e](std::initializer_list<Effect> list) {
    for (Effect x : list) e.push_back(x);
  };
  switch (variant_) {
    case ref::DecoderVariant::Literal:
      add({Effect::DecodeUnormAddress,
           profile_->foldsMultiplyByConstantZero ? Effect::DecodeModByZeroFolded : Effect::DecodeGlslMod,
           Effect::SamplerNearest});
      break;
    case ref::DecoderVariant::Paper:
      if (tex_->index.encoding != ref::IndexEncoding::NormalizedFloat) add({Effect::DecodeUnormAddress});
      add({Effect::DecodeGlslMod, Effect::SamplerNearest});
      break;
    case ref::DecoderVariant::TexelCentre:
      add({Effect::DecodeIntegerAddress, Effect::SamplerNearest});
      break;
    case ref::DecoderVariant::TexelFetch:
      add({Effect::DecodeIntegerAddress});
      break;
  }
  return e;
}

std::array<float, 4> TimeVaryingDecoderEmu::indexTexel(const std::array<int, 3>& t) const {
  std::array<float, 4> v{};
  const std::uint32_t* c = &tex_->index.texels[4 * texelOffset(tex_->index.dims, t)];
  for (int i = 0; i < 4; ++i) switch (tex_->index.encoding) {
      case ref::IndexEncoding::NormalizedRgba16:
        v[i] = unormToFloat(c[i], 16);
        break;
      case ref::IndexEncoding::NormalizedFloat: {
        const float f = std::bit_cast<float>(c[i]);
        v[i] = profile_->flushDenormals ? flushDenormal(f) : f;
        break;
      }
      default:
        v[i] = unormToFloat(c[i], 8);
    }
  return v;
}

std::array<float, 4> TimeVaryingDecoderEmu::refinementTexel(const std::array<int, 3>& t) const {
  std::array<float, 4> v{};
  const std::uint8_t* c = &tex_->refinement.texels[4 * texelOffset(tex_->refinement.dims, t)];
  for (int i = 0; i < 4; ++i) v[i] = unormToFloat(c[i], 8);
  return v;
}

std::array<int, 3> TimeVaryingDecoderEmu::nearest(const ref::Dims3& d, float s, float t, float r) const {
  const float c[3] = {s, t, r};
  std::array<int, 3> i{};
  for (int a = 0; a < 3; ++a) i[a] = nearestTexelIndex(c[a], d[a], ref::Wrap::ClampToEdge, *profile_);
  return i;
}

DecodedSample TimeVaryingDecoderEmu::decode(int step, glm::vec3 p) const {
  DecodedSample out;
  if (p.x < 0.0f || p.y < 0.0f || p.z < 0.0f || p.x > 1.0f || p.y > 1.0f || p.z > 1.0f) {
    out.discarded = true;
    return out;
  }
  const ref::TimeVaryingLayout& L = tex_->layout;
  const auto slot = ref::indexSlot(L, step);
  const float S = static_cast<float>(L.indexSlots), n = static_cast<float>(L.cells);
  const float pc[3] = {p.x, p.y, p.z};
  std::array<float, 4> c{};
  float refCoord[3] = {0, 0, 0};
  switch (variant_) {
    case ref::DecoderVariant::Literal:
    case ref::DecoderVariant::Paper: {
      // literal: origin + texCoord / DR (DR = 8 = S); paper: slotOrigin + p * (1 / S). Both exact.
      float ic[3];
      for (int a = 0; a < 3; ++a) {
        const float origin = static_cast<float>(slot[a]) / S;
        ic[a] = variant_ == ref::DecoderVariant::Literal ? origin + pc[a] / 8.0f : origin + pc[a] * (1.0f / S);
      }
      out.indexTexel = nearest(tex_->index.dims, ic[0], ic[1], ic[2]);
      c = forcedWeights(indexWeights_, indexTexel(out.indexTexel), ic);
      for (int a = 0; a < 3; ++a) {
        float offset;
        if (variant_ == ref::DecoderVariant::Literal) {
          // mod(texCoord, 8 / 128): the integer quotient is 0; the compiler folds 0 * floor(x / 0).
          offset = profile_->foldsMultiplyByConstantZero ? pc[a] : glslMod(pc[a], 0.0f);
        } else {
          offset = glslMod(pc[a], 1.0f / n) * (n / static_cast<float>(L.blockSlots));
        }
        refCoord[a] = c[a] + offset;
      }
      out.refined = c[3] == 1.0f;
      if (out.refined) {
        out.refinementTexel = nearest(tex_->refinement.dims, refCoord[0], refCoord[1], refCoord[2]);
        c = forcedWeights(refinementWeights_, refinementTexel(out.refinementTexel), refCoord);
      }
      break;
    }
    case ref::DecoderVariant::TexelCentre: {
      const float indexSize = static_cast<float>(L.indexSlots * L.cells), side = static_cast<float>(L.side);
      const float r = static_cast<float>(L.blockSide), refSize = static_cast<float>(L.blockSlots * L.blockSide);
      float cell[3], ic[3];
      for (int a = 0; a < 3; ++a) {
        cell[a] = std::min(std::floor(pc[a] * n), n - 1.0f);
        ic[a] = ((static_cast<float>(slot[a] * L.cells) + cell[a]) + 0.5f) / indexSize;
      }
      out.indexTexel = nearest(tex_->index.dims, ic[0], ic[1], ic[2]);
      c = forcedWeights(indexWeights_, indexTexel(out.indexTexel), ic);
      out.refined = c[3] == 1.0f;
      if (out.refined) {
        for (int a = 0; a < 3; ++a) {
          const float block = std::floor(c[a] * 255.0f + 0.5f);
          const float voxel = std::min(std::floor(pc[a] * side), side - 1.0f);
          refCoord[a] = ((block * r + (voxel - cell[a] * r)) + 0.5f) / refSize;
        }
        out.refinementTexel = nearest(tex_->refinement.dims, refCoord[0], refCoord[1], refCoord[2]);
        c = forcedWeights(refinementWeights_, refinementTexel(out.refinementTexel), refCoord);
      }
      break;
    }
    case ref::DecoderVariant::TexelFetch: {
      // The texel a texelFetch reads: itself inside the texture; outside, the clamped one where the
      // driver clamps, else none (zero, kNoTexel).
      auto resolve = [&](const ref::Dims3& d, std::array<int, 3> t) {
        if (inside(d, t)) return t;
        if (!profile_->texelFetchOutOfRangeClamps) return ref::kNoTexel;
        for (int a = 0; a < 3; ++a) t[a] = std::clamp(t[a], 0, d[a] - 1);
        return t;
      };
      auto fetch = [&](const ref::Dims3& d, const std::array<int, 3>& t, bool index) {
        if (t == ref::kNoTexel) return std::array<float, 4>{};
        if (!force_) return index ? indexTexel(t) : refinementTexel(t);
        // Forced: the weight stage at the texel's centre, (t + 0.5) / size.
        float centre[3];
        for (int a = 0; a < 3; ++a) centre[a] = (static_cast<float>(t[a]) + 0.5f) / static_cast<float>(d[a]);
        return index ? forcedWeights(indexWeights_, indexTexel(t), centre)
                     : forcedWeights(refinementWeights_, refinementTexel(t), centre);
      };
      std::array<int, 3> cell{};
      for (int a = 0; a < 3; ++a) {
        cell[a] = std::min(glslInt(pc[a] * n), L.cells - 1);
        out.indexTexel[a] = slot[a] * L.cells + cell[a];
      }
      out.indexTexel = resolve(tex_->index.dims, out.indexTexel);
      c = fetch(tex_->index.dims, out.indexTexel, true);
      out.refined = c[3] == 1.0f;
      if (out.refined) {
        for (int a = 0; a < 3; ++a) {
          const int block = glslInt(c[a] * 255.0f + 0.5f);
          const int voxel = std::min(glslInt(pc[a] * static_cast<float>(L.side)), L.side - 1);
          out.refinementTexel[a] = block * L.blockSide + (voxel - cell[a] * L.blockSide);
        }
        out.refinementTexel = resolve(tex_->refinement.dims, out.refinementTexel);
        c = fetch(tex_->refinement.dims, out.refinementTexel, false);
      }
      break;
    }
  }
  out.value = c;
  return out;
}

std::vector<ref::TexelFetch> fetchesOf(const EmulatedDecode& decoded) {
  return {decoded.samples.begin(), decoded.samples.end()};
}

EmulatedDecode emulateDecodePlanes(const ref::TimeVaryingTextures& textures, ref::DecoderVariant variant, int step,
                                   const ref::PlaneFrame& frame, const PrecisionProfile& profile, int threads,
                                   bool forceAllEffects) {
  const TimeVaryingDecoderEmu decoder(textures, variant, profile, forceAllEffects);
  const std::size_t perPlane = static_cast<std::size_t>(frame.width) * frame.height;
  EmulatedDecode out{{frame.width, frame.height, frame.planes, std::vector<ref::Rgba8>(perPlane * frame.planes)},
                     std::vector<DecodedSample>(perPlane * frame.planes)};
  const glm::vec3 dx(frame.dx), dy(frame.dy);
  ref::parallelFor(frame.planes, threads, [&](int k) {
    const glm::vec3 o(frame.planeOrigin(k));
    for (int j = 0; j < frame.height; ++j)
      for (int i = 0; i < frame.width; ++i) {
        const float fx = static_cast<float>(i) + 0.5f, fy = static_cast<float>(j) + 0.5f;
        const glm::vec3 p((o.x + fx * dx.x) + fy * dy.x, (o.y + fx * dx.y) + fy * dy.y, (o.z + fx * dx.z) + fy * dy.z);
        const std::size_t idx = perPlane * static_cast<std::size_t>(k) + static_cast<std::size_t>(i) +
                                static_cast<std::size_t>(frame.width) * j;
        out.samples[idx] = decoder.decode(step, p);
        out.colours.colours[idx] =
            out.samples[idx].discarded ? ref::Rgba8{0, 0, 0, 0} : outputRgba8(out.samples[idx].value);
      }
  });
  return out;
}

ref::RgbaStack emulateComposite(const ref::TimeVaryingTextures& textures, ref::DecoderVariant variant, int step,
                                const ref::PlaneFrame& frame, const PrecisionProfile& profile, int threads,
                                bool flushEachPass, bool forceAllEffects) {
  const TimeVaryingDecoderEmu decoder(textures, variant, profile, forceAllEffects);
  const AlphaBlendEmu blend(profile, flushEachPass);
  ref::RgbaStack out{frame.width, frame.height, 1,
                     std::vector<ref::Rgba8>(static_cast<std::size_t>(frame.width) * frame.height)};
  const glm::vec3 dx(frame.dx), dy(frame.dy);
  // Rows are independent: each pixel blends its own slices, back (k = planes - 1) to front.
  ref::parallelFor(frame.height, threads, [&](int j) {
    for (int i = 0; i < frame.width; ++i) {
      AlphaBlendEmu::Pixel px = blend.cleared();
      for (int k = frame.planes - 1; k >= 0; --k) {
        const glm::vec3 o(frame.planeOrigin(k));
        const float fx = static_cast<float>(i) + 0.5f, fy = static_cast<float>(j) + 0.5f;
        const glm::vec3 p((o.x + fx * dx.x) + fy * dy.x, (o.y + fx * dx.y) + fy * dy.y, (o.z + fx * dx.z) + fy * dy.z);
        const DecodedSample s = decoder.decode(step, p);
        if (!s.discarded) blend.blend(px, s.value);
      }
      out.colours[static_cast<std::size_t>(i) + static_cast<std::size_t>(frame.width) * j] = blend.resolve(px);
    }
  });
  return out;
}

}  // namespace voxref::emu
