#include "emulation/effects.h"

#include <array>
#include <utility>

namespace voxref::emu {
namespace {

struct EffectText {
  Effect effect;
  std::string_view id;
  std::string_view description;
};

constexpr std::array<EffectText, 31> kEffects{{
    {Effect::AddressDivision, "address.float32_division", "texture coordinate (p 2^l + 0.5) / D rounded in float32"},
    {Effect::TextureBricks, "address.texture_bricks",
     "grid textures split into overlapping bricks; per-brick address and discard"},
    {Effect::TexelUnorm8, "texel.unorm8", "texel values quantized to unorm8"},
    {Effect::TexelUnorm16, "texel.unorm16", "texel values quantized to unorm16"},
    {Effect::TexelHalf, "texel.half", "texel values rounded to binary16"},
    {Effect::TexelFloat32, "texel.float32", "texel values rounded to binary32"},
    {Effect::UnormToFloatReciprocal, "texel.unorm_to_float_reciprocal", "unorm texel to float as k * fl(1/(2^b-1))"},
    {Effect::SamplerAos8Bit, "sampler.aos_8bit",
     "8 subtexel weight bits, 8-bit lerps rounded per stage (llvmpipe AoS)"},
    {Effect::SamplerFloatWeights, "sampler.float_weights", "float32 weights w = fract(fl(s N) - 0.5)"},
    {Effect::LerpFused, "sampler.lerp_fused", "lerp a + w (b - a) with one rounding (FMA)"},
    {Effect::LerpUnfused, "sampler.lerp_unfused", "lerp a + w (b - a) with three roundings"},
    {Effect::SamplerNearest, "sampler.nearest", "nearest texel, no weight stage"},
    {Effect::BorderTexels, "sampler.border_texels", "out-of-range taps take the border colour before filtering"},
    {Effect::TileCacheAliasing, "sampler.tile_cache_aliasing",
     "taps sharing a texture tile-cache slot read the later tile (softpipe)"},
    {Effect::FlushDenormals, "float.flush_denormals", "denormals flushed to zero (FTZ/DAZ)"},
    {Effect::OutputUnorm8, "output.unorm8", "fragment colour to unorm8: clamp, round half to even of fl(x 255)"},
    {Effect::OutputUnorm12, "output.unorm12", "fragment colour to unorm12 (CPU-only framebuffer)"},
    {Effect::OutputUnorm16HalfEven, "output.unorm16_half_even", "fragment colour to unorm16: round half to even"},
    {Effect::OutputUnorm16HalfUp, "output.unorm16_half_up", "colour to unorm16 at tile write-back: round half up"},
    {Effect::BlendSaturatingPerPass, "blend.saturating_per_pass",
     "integer add / reverse subtract, saturating, every pass"},
    {Effect::BlendFloat32, "blend.float32", "float32 add / reverse subtract, no clamp"},
    {Effect::StoreHalfTowardZeroPerPass, "store.half_toward_zero_per_pass",
     "RGBA16F stored as binary16 toward zero after every pass"},
    {Effect::FloatTileCache, "framebuffer.float_tile_cache",
     "float32 tile cache: per-pass clamp, one quantization at read-back"},
    {Effect::StoreHalfTowardZeroOnFlush, "store.half_toward_zero_on_flush",
     "RGBA16F accumulated in float32, stored toward zero once"},
    {Effect::BlendAlphaMulnorm, "blend.alpha_mulnorm",
     "RGBA8 SRC_ALPHA/ONE_MINUS_SRC_ALPHA: 8-bit mulnorm products, saturating add"},
    {Effect::BlendAlphaFloat, "blend.alpha_float32", "SRC_ALPHA/ONE_MINUS_SRC_ALPHA in float32, clamped per pass"},
    {Effect::DecodeUnormAddress, "decode.unorm_address",
     "refinement origins read from unorm texels: k * fl(1/(2^b-1))"},
    {Effect::DecodeGlslMod, "decode.glsl_mod",
     "position inside a coarse cell by mod(x, y) = x - y floor(x / y) in float32"},
    {Effect::DecodeModByZeroFolded, "decode.mod_by_zero_folded",
     "literal shader: mod(x, 8 / 128) = mod(x, 0) folded to x"},
    {Effect::DecodeIntegerAddress, "decode.integer_address",
     "integer block and voxel numbers, texel centres or texelFetch"},
    {Effect::FlushEachPass, "framebuffer.flush_each_pass",
     "glFinish after every pass: tile stored and reloaded per pass"},
}};

const EffectText& lookup(Effect e) {
  for (const EffectText& t : kEffects)
    if (t.effect == e) return t;
  return kEffects[0];
}

}  // namespace

std::string_view effectId(Effect e) { return lookup(e).id; }
std::string_view effectDescription(Effect e) { return lookup(e).description; }

std::vector<std::string_view> effectIds(const std::vector<Effect>& effects) {
  std::vector<std::string_view> ids;
  for (Effect e : effects) ids.push_back(effectId(e));
  return ids;
}

}  // namespace voxref::emu
