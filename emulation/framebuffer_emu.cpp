#include "emulation/framebuffer_emu.h"

#include <algorithm>
#include <bit>
#include <limits>
#include <stdexcept>

#include "emulation/float32.h"

namespace voxref::emu {

BlendEmu::BlendEmu(ref::FramebufferFormat format, const PrecisionProfile& profile, bool flushEachPass, int width,
                   int height, bool forceAllEffects)
    : format_(format),
      profile_(&profile),
      // The 12-bit buffer is voxref's own definition, the same for every profile.
      model_(format == ref::FramebufferFormat::RGBA12 ? FramebufferModel::QuantizePerPass : profile.framebuffer),
      flushEachPass_(flushEachPass),
      bits_(ref::unormBits(format)),
      force_(forceAllEffects),
      clampLo_(-std::numeric_limits<float>::infinity()),
      clampHi_(std::numeric_limits<float>::infinity()) {
  if (model_ == FramebufferModel::FloatTileCache &&
      (width > profile.maxModelledTargetWidth || height > profile.maxModelledTargetHeight))
    throw std::invalid_argument(
        "profile " + std::string(profile.name) + " models targets up to " +
        std::to_string(profile.maxModelledTargetWidth) + "x" + std::to_string(profile.maxModelledTargetHeight) +
        " (tile-cache eviction beyond), got " + std::to_string(width) + "x" + std::to_string(height));
}

std::vector<Effect> BlendEmu::effects() const {
  std::vector<Effect> e;
  if (model_ == FramebufferModel::QuantizePerPass) {
    switch (format_) {
      case ref::FramebufferFormat::RGBA8:
        e = {Effect::OutputUnorm8, Effect::BlendSaturatingPerPass};
        break;
      case ref::FramebufferFormat::RGBA12:
        e = {Effect::OutputUnorm12, Effect::BlendSaturatingPerPass};
        break;
      case ref::FramebufferFormat::RGBA16:
        e = {Effect::OutputUnorm16HalfEven, Effect::BlendSaturatingPerPass};
        break;
      case ref::FramebufferFormat::RGBA16F:
        e = {Effect::BlendFloat32, Effect::StoreHalfTowardZeroPerPass};
        break;
      case ref::FramebufferFormat::RGBA32F:
        e = {Effect::BlendFloat32};
        if (profile_->flushDenormals) e.push_back(Effect::FlushDenormals);
        break;
    }
    return e;
  }
  e = {Effect::FloatTileCache, Effect::BlendFloat32};
  switch (format_) {
    case ref::FramebufferFormat::RGBA8:
      e.push_back(Effect::OutputUnorm8);
      break;
    case ref::FramebufferFormat::RGBA16:
      e.push_back(profile_->unorm16Store == UnormRounding::HalfUp ? Effect::OutputUnorm16HalfUp
                                                                  : Effect::OutputUnorm16HalfEven);
      break;
    case ref::FramebufferFormat::RGBA16F:
      e.push_back(Effect::StoreHalfTowardZeroOnFlush);
      break;
    default:
      break;
  }
  if (flushEachPass_ && format_ != ref::FramebufferFormat::RGBA32F) e.push_back(Effect::FlushEachPass);
  return e;
}

std::uint32_t BlendEmu::store(float value) const {
  switch (format_) {
    case ref::FramebufferFormat::RGBA8:
    case ref::FramebufferFormat::RGBA12:
      return floatToUnormHalfEven(value, bits_);
    case ref::FramebufferFormat::RGBA16:
      return profile_->unorm16Store == UnormRounding::HalfUp ? floatToUnormHalfUp(value, 16)
                                                             : floatToUnormHalfEven(value, 16);
    case ref::FramebufferFormat::RGBA16F:
      return floatToHalfTowardZero(value);
    case ref::FramebufferFormat::RGBA32F:
      return std::bit_cast<std::uint32_t>(value);
  }
  return 0;
}

// The clamp stage of a float format, run only when forced: its bounds are the format's range
// (-inf, +inf), and NaN passes as it is, so it changes no bit.
float BlendEmu::formatClamp(float x) const { return x < clampLo_ ? clampLo_ : (x > clampHi_ ? clampHi_ : x); }

float BlendEmu::reload(std::uint32_t code) const {
  if (bits_) return unormToFloat(code, bits_);
  if (format_ == ref::FramebufferFormat::RGBA16F) return halfToFloat(static_cast<std::uint16_t>(code));
  return std::bit_cast<float>(code);
}

void BlendEmu::blend(PixelState& px, float src, ref::BlendEquation eq) const {
  const bool add = eq == ref::BlendEquation::FuncAdd;
  if (model_ == FramebufferModel::QuantizePerPass) {
    if (bits_) {  // lp_bld_blend.c: llvm.uadd.sat / llvm.usub.sat on unorm lanes
      const std::uint32_t s = floatToUnormHalfEven(src, bits_);
      const std::uint32_t maxCode = (std::uint32_t{1} << bits_) - 1u;
      px.code = add ? std::min(px.code + s, maxCode) : (px.code > s ? px.code - s : 0u);
      return;
    }
    if (format_ == ref::FramebufferFormat::RGBA16F) {  // lp_state_fs.c: half -> float, blend, float -> half RTZ
      const float d = halfToFloat(static_cast<std::uint16_t>(px.code));
      const float s = force_ ? formatClamp(src) : src;
      const float r = add ? s + d : d - s;
      px.code = floatToHalfTowardZero(force_ ? formatClamp(r) : r);
      return;
    }
    auto ftz = [this](float x) { return profile_->flushDenormals ? flushDenormal(x) : x; };
    const float d = ftz(std::bit_cast<float>(px.code)), s = ftz(force_ ? formatClamp(src) : src);
    const float r = ftz(add ? s + d : d - s);
    px.code = std::bit_cast<std::uint32_t>(force_ ? formatClamp(r) : r);
    return;
  }
  // FloatTileCache (sp_quad_blend.c blend_single_add_one_one / blend_quad). CLAMP of u_math.h
  // maps NaN to the lower bound.
  auto clampUnit = [](float x) { return x > 0.0f ? (x > 1.0f ? 1.0f : x) : 0.0f; };
  const bool clamp = bits_ != 0;
  const float s = clamp ? clampUnit(src) : force_ ? formatClamp(src) : src;
  float r = add ? s + px.value : px.value - s;
  if (clamp)
    r = clampUnit(r);
  else if (force_)
    r = formatClamp(r);
  // A float32 tile stored and reloaded is a bit cast: pruned unless forced.
  const bool flush = flushEachPass_ || (force_ && format_ == ref::FramebufferFormat::RGBA32F);
  px.value = flush ? reload(store(r)) : r;
}

std::uint32_t BlendEmu::resolve(const PixelState& px) const {
  return model_ == FramebufferModel::QuantizePerPass ? px.code : store(px.value);
}

}  // namespace voxref::emu

namespace voxref::emu {

std::uint8_t mulnorm8(std::uint8_t x, std::uint8_t y) {
  const unsigned t = static_cast<unsigned>(x) * y;
  return static_cast<std::uint8_t>((t + (t >> 8) + 128) >> 8);
}

void AlphaBlendEmu::blend(Pixel& px, const std::array<float, 4>& src) const {
  if (profile_->framebuffer == FramebufferModel::QuantizePerPass) {
    std::array<std::uint8_t, 4> s{};
    for (int c = 0; c < 4; ++c) s[c] = static_cast<std::uint8_t>(floatToUnormHalfEven(src[c], 8));
    const std::uint8_t a = s[3], oneMinusA = static_cast<std::uint8_t>(255 - a);
    for (int c = 0; c < 4; ++c)
      px.code[c] = static_cast<std::uint8_t>(std::min(255, mulnorm8(s[c], a) + mulnorm8(px.code[c], oneMinusA)));
    return;
  }
  auto clampUnit = [](float x) { return x > 0.0f ? (x > 1.0f ? 1.0f : x) : 0.0f; };  // u_math.h CLAMP: NaN -> 0
  const float a = clampUnit(src[3]);
  const float oneMinusA = 1.0f - a;
  for (int c = 0; c < 4; ++c) {
    const float s = clampUnit(src[c]);
    const float sa = s * a;
    const float dOma = px.value[c] * oneMinusA;
    px.value[c] = clampUnit(sa + dOma);
    if (flush_) px.value[c] = unormToFloat(floatToUnormHalfEven(px.value[c], 8), 8);
  }
}

std::array<std::uint8_t, 4> AlphaBlendEmu::resolve(const Pixel& px) const {
  if (profile_->framebuffer == FramebufferModel::QuantizePerPass) return px.code;
  std::array<std::uint8_t, 4> out{};
  for (int c = 0; c < 4; ++c) out[c] = static_cast<std::uint8_t>(floatToUnormHalfEven(px.value[c], 8));
  return out;
}

std::vector<Effect> AlphaBlendEmu::effects() const {
  if (profile_->framebuffer == FramebufferModel::QuantizePerPass)
    return {Effect::OutputUnorm8, Effect::BlendAlphaMulnorm};
  if (flush_) return {Effect::FloatTileCache, Effect::BlendAlphaFloat, Effect::OutputUnorm8, Effect::FlushEachPass};
  return {Effect::FloatTileCache, Effect::BlendAlphaFloat, Effect::OutputUnorm8};
}

}  // namespace voxref::emu
