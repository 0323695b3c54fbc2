// Effects: the stages of a GL pipeline that can change a bit of the output (docs/design.md, "Scenes
// and effects"). The emulator derives the list from the scene's GL state and the profile and
// composes only those stages; every case records the list it simulated.
#pragma once

#include <string_view>
#include <vector>

namespace voxref::emu {

enum class Effect {
  AddressDivision,             // texture coordinate (p 2^l + 0.5) / D rounds (D not a power of two)
  TextureBricks,               // grids split into bricks: per-brick address and discard
  TexelUnorm8,                 // texels stored as unorm8
  TexelUnorm16,                // texels stored as unorm16
  TexelHalf,                   // texels stored as binary16
  TexelFloat32,                // texels stored as binary32
  UnormToFloatReciprocal,      // unorm texel to float as k * fl(1 / (2^b - 1))
  SamplerAos8Bit,              // llvmpipe 8-bit path: 8 subtexel bits, 8-bit lerps rounded per stage
  SamplerFloatWeights,         // float32 weights from fl(s N) - 0.5
  LerpFused,                   // a + w (b - a) with one rounding (FMA)
  LerpUnfused,                 // a + w (b - a) with three roundings
  SamplerNearest,              // nearest texel, no weights
  BorderTexels,                // out-of-range taps take the border colour before filtering
  TileCacheAliasing,           // softpipe: taps of a lookup alias in the 16-slot texture tile cache
  FlushDenormals,              // FTZ / DAZ
  OutputUnorm8,                // fragment colour -> unorm8, round half to even, clamp
  OutputUnorm12,               // fragment colour -> unorm12 (CPU-only framebuffer)
  OutputUnorm16HalfEven,       // fragment colour -> unorm16, round half to even
  OutputUnorm16HalfUp,         // colour -> unorm16 at tile write-back, round half up (softpipe)
  BlendSaturatingPerPass,      // integer add / reverse subtract saturating at 0 and 2^b - 1, every pass
  BlendFloat32,                // float32 add / reverse subtract, no clamp
  StoreHalfTowardZeroPerPass,  // RGBA16F: float32 blend, stored as binary16 rounded toward zero every pass
  FloatTileCache,              // softpipe: float32 tile, source and result clamped per pass, stored once
  StoreHalfTowardZeroOnFlush,  // softpipe RGBA16F: float32 accumulation, binary16 toward zero once
  FlushEachPass,               // glFinish after every pass: the tile is stored and reloaded per pass
  BlendAlphaMulnorm,           // RGBA8 SRC_ALPHA / ONE_MINUS_SRC_ALPHA in 8 bits: mulnorm products, saturating add
  BlendAlphaFloat,             // SRC_ALPHA / ONE_MINUS_SRC_ALPHA in float32 (softpipe's tile)
  DecodeUnormAddress,          // refinement origins read back from unorm texels (k * fl(1/(2^b-1)))
  DecodeGlslMod,               // the position inside a coarse cell by GLSL mod(): x - y floor(x / y)
  DecodeModByZeroFolded,       // the literal shader's mod(x, 8 / 128 = 0) folded to x by the compiler
  DecodeIntegerAddress,        // integer block and voxel numbers (texel centres or texelFetch)
};

std::string_view effectId(Effect e);           // dotted id: "sampler.aos_8bit"
std::string_view effectDescription(Effect e);  // one line for reports
std::vector<std::string_view> effectIds(const std::vector<Effect>& effects);

}  // namespace voxref::emu
