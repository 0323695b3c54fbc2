// The paper's hardware method as data (Teitzel et al. 1999, section 6 and the pseudo code of
// createTextures / dataToTexture / calcValueRect): one 3D texture per component grid and the
// sequence of blended passes that evaluates eq. 11 on a sampling plane.
//
// The GL path (gpu/) and its emulation (emulation/) both consume this description, so they draw
// the same texels in the same order with the same blend equations.
//
// Scaling policy (section 6): the framebuffer clamps to [0, 1] after every blend, so the paper
// scales every texture by f / n+ (f = 1 for positive grids, f = 2 for negative ones, which carry
// their factor 2 in the texels) and multiplies the read-back plane by n+. `Unscaled` stores the
// plain data and draws every negative grid twice; Figure 9 shows that no order of passes is then
// correct for all points.
//
// Texture sizing: `Padded` is the paper's 2^(l+1) texels per axis (power-of-two textures, data in
// texels 0..2^l, zeros after); `Exact` uses 2^l + 1 texels. Either way node a of an axis with
// level l sits at the centre of texel a, and the texture coordinate of sample coordinate p is
//     u = (p * 2^l + 0.5) / D,   D = texels on that axis
// (the paper's s/2 + 1/(4 * 2^l) for D = 2^(l+1)). p * 2^l and + 0.5 are exact in float32 on the
// plane-frame lattice (plane_frame.h); the division is the one rounding of the address.
//
// Bricks. GL 4.5 guarantees GL_MAX_3D_TEXTURE_SIZE >= 2048 (table 23.53), so a grid texture with
// more than `maxExtent` (default 2048) texels on an axis (level >= 11) is split along that axis
// into bricks of maxExtent texels that overlap by one texel: brick b serves the cells
// [b C, (b+1) C) of its axis, C = maxExtent - 1 (the last brick also serves node 2^l), and holds
// the texels [b C, b C + maxExtent). Every brick is drawn as its own pass with the grid's blend
// equation; a fragment whose node coordinate c = p 2^l lies outside the brick's cells is
// discarded, so each sample still blends each grid exactly once. Inside a brick the coordinate
// is u = (c + 0.5 - origin) / extent; c + 0.5 - origin is exact (an integer origin below 2^13
// subtracted from a lattice value), so the division is still the only rounding. Textures that
// fit are one brick with origin 0 and the same bits as without bricking.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "reference/common/gl_state.h"
#include "reference/common/volume.h"
#include "reference/sparsegrid/combination.h"

namespace voxref::ref {

enum class TextureSizing { Padded, Exact };
enum class ScalingPolicy { Scaled, Unscaled };
std::string_view name(TextureSizing s);
std::string_view name(ScalingPolicy s);
std::optional<TextureSizing> parseTextureSizing(std::string_view s);
std::optional<ScalingPolicy> parseScalingPolicy(std::string_view s);

struct GridTexture {
  Levels3 levels{};
  Dims3 dims{};                      // texels per axis (of this brick)
  std::vector<std::uint32_t> codes;  // red-channel codes (texel_format.h), x fastest
  std::array<int, 3> origin{};       // first texel of the brick in the grid's texture
  std::array<int, 3> cellLo{};       // node coordinates served: cellLo <= c < cellHi per axis
  std::array<int, 3> cellHi{};
  int grid = 0;  // index of the component grid (combination.h order)
};

// True when the brick serves node coordinate c (per axis: cellLo <= c < cellHi).
bool servesCell(const GridTexture& brick, double cx, double cy, double cz);

struct CombinationPass {
  int texture = 0;
  BlendEquation equation = BlendEquation::FuncAdd;
};

struct CombinationTextures {
  TexelFormat format = TexelFormat::R16;
  TextureSizing sizing = TextureSizing::Padded;
  ScalingPolicy scaling = ScalingPolicy::Scaled;
  int positiveCount = 0;       // n+
  double readbackScale = 1.0;  // n+ when scaled, 1 when unscaled
  std::vector<GridTexture> textures;
  std::vector<CombinationPass> passes;  // in drawing order
};

inline constexpr int kGuaranteedMax3DTextureSize = 2048;  // GL 4.5 core, minimum of GL_MAX_3D_TEXTURE_SIZE

struct CombinationTextureOptions {
  TexelFormat format = TexelFormat::R16;  // the paper used 16-bit luminance
  TextureSizing sizing = TextureSizing::Padded;
  ScalingPolicy scaling = ScalingPolicy::Scaled;
  int maxExtent = kGuaranteedMax3DTextureSize;  // texels per axis and brick (>= 3)
};

// Texel values: f * value / n+ (scaled) or value (unscaled), computed in double and encoded once
// with encodeTexel. Passes: positive grids with FUNC_ADD, then negative grids with
// FUNC_REVERSE_SUBTRACT (once scaled, twice unscaled), in the grid order of combination.h; a
// bricked grid's pass is one pass per brick. Throws std::invalid_argument for maxExtent < 3.
CombinationTextures buildCombinationTextures(const Combination& combination, const CombinationTextureOptions& options);

// Texels per axis of a grid level under a sizing policy.
int textureExtent(int level, TextureSizing sizing);
// The exact texture coordinate of sample coordinate p in a brick starting at texel `origin`
// (see the file comment).
double textureCoordinate(double p, int level, int extent, int origin = 0);
// Number of component grids split into more than one brick.
int brickedGridCount(const CombinationTextures& textures);
// GL memory of the textures (all channels of the format).
std::size_t textureBytes(const CombinationTextures& textures);

}  // namespace voxref::ref
