#include "reference/sparsegrid/combination_textures.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "reference/common/rounding.h"
#include "reference/common/texel_format.h"

namespace voxref::ref {

std::string_view name(TextureSizing s) { return s == TextureSizing::Padded ? "padded" : "exact"; }
std::string_view name(ScalingPolicy s) { return s == ScalingPolicy::Scaled ? "scaled" : "unscaled"; }

std::optional<TextureSizing> parseTextureSizing(std::string_view s) {
  if (s == "padded") return TextureSizing::Padded;
  if (s == "exact") return TextureSizing::Exact;
  return std::nullopt;
}

std::optional<ScalingPolicy> parseScalingPolicy(std::string_view s) {
  if (s == "scaled") return ScalingPolicy::Scaled;
  if (s == "unscaled") return ScalingPolicy::Unscaled;
  return std::nullopt;
}

int textureExtent(int level, TextureSizing sizing) {
  return sizing == TextureSizing::Padded ? 1 << (level + 1) : (1 << level) + 1;
}

double textureCoordinate(double p, int level, int extent, int origin) {
  return (scaleByPowerOfTwo(p, level) + 0.5 - origin) / extent;
}

bool servesCell(const GridTexture& b, double cx, double cy, double cz) {
  const double c[3] = {cx, cy, cz};
  for (int a = 0; a < 3; ++a)
    if (c[a] < b.cellLo[a] || c[a] >= b.cellHi[a]) return false;
  return true;
}

int brickedGridCount(const CombinationTextures& textures) {
  int count = 0;
  for (std::size_t i = 0; i < textures.textures.size(); ++i)
    if (textures.textures[i].origin != std::array<int, 3>{0, 0, 0} &&
        (i == 0 || textures.textures[i - 1].grid != textures.textures[i].grid ||
         textures.textures[i - 1].origin == std::array<int, 3>{0, 0, 0}))
      ++count;
  return count;
}

namespace {

struct AxisBrick {
  int origin, extent, cellLo, cellHi;
};

// Bricks along one axis of a grid of level l whose texture has `texels` texels.
std::vector<AxisBrick> axisBricks(int level, int texels, int maxExtent) {
  const int nodes = 1 << level;  // cells 0 .. nodes - 1, node `nodes` served by the last brick
  if (texels <= maxExtent) return {{0, texels, 0, nodes + 1}};
  const int cells = maxExtent - 1;
  std::vector<AxisBrick> out;
  for (int lo = 0; lo < nodes; lo += cells) {
    const bool last = lo + cells >= nodes;
    out.push_back({lo, std::min(maxExtent, texels - lo), lo, last ? nodes + 1 : lo + cells});
  }
  return out;
}

}  // namespace

CombinationTextures buildCombinationTextures(const Combination& combination, const CombinationTextureOptions& options) {
  CombinationTextures out;
  out.format = options.format;
  out.sizing = options.sizing;
  out.scaling = options.scaling;
  out.positiveCount = combination.positiveCount();
  const bool scaled = options.scaling == ScalingPolicy::Scaled;
  out.readbackScale = scaled ? combination.positiveCount() : 1.0;
  if (options.maxExtent < 3) throw std::invalid_argument("texture bricks need at least 3 texels per axis");
  const std::uint32_t zeroCode = encodeTexel(options.format, 0.0);
  const auto& grids = combination.grids();
  std::vector<std::vector<int>> bricksOfGrid(grids.size());
  for (std::size_t gi = 0; gi < grids.size(); ++gi) {
    const ComponentGrid& g = grids[gi];
    Dims3 full{};
    for (int a = 0; a < 3; ++a) full[a] = textureExtent(g.levels[a], options.sizing);
    std::vector<std::uint32_t> codes(sampleCount(full), zeroCode);
    // dataToTexture: t = f / n+ * d(node); negative grids carry f = 2 (pseudo code, section 6).
    const double factor = scaled ? (g.coefficient < 0 ? 2.0 : 1.0) : 1.0;
    const auto& d = g.values.dims();
    for (int z = 0; z < d[2]; ++z)
      for (int y = 0; y < d[1]; ++y)
        for (int x = 0; x < d[0]; ++x) {
          const double v = scaled ? factor * g.values.at(x, y, z) / combination.positiveCount() : g.values.at(x, y, z);
          codes[static_cast<std::size_t>(x) +
                static_cast<std::size_t>(full[0]) * (y + static_cast<std::size_t>(full[1]) * z)] =
              encodeTexel(options.format, v);
        }
    const auto bx = axisBricks(g.levels[0], full[0], options.maxExtent),
               by = axisBricks(g.levels[1], full[1], options.maxExtent),
               bz = axisBricks(g.levels[2], full[2], options.maxExtent);
    for (const AxisBrick& z : bz)
      for (const AxisBrick& y : by)
        for (const AxisBrick& x : bx) {
          GridTexture t;
          t.levels = g.levels;
          t.grid = static_cast<int>(gi);
          t.dims = {x.extent, y.extent, z.extent};
          t.origin = {x.origin, y.origin, z.origin};
          t.cellLo = {x.cellLo, y.cellLo, z.cellLo};
          t.cellHi = {x.cellHi, y.cellHi, z.cellHi};
          if (bx.size() == 1 && by.size() == 1 && bz.size() == 1) {
            t.codes = std::move(codes);
          } else {
            t.codes.resize(sampleCount(t.dims));
            for (int k = 0; k < z.extent; ++k)
              for (int j = 0; j < y.extent; ++j)
                for (int i = 0; i < x.extent; ++i)
                  t.codes[static_cast<std::size_t>(i) +
                          static_cast<std::size_t>(x.extent) * (j + static_cast<std::size_t>(y.extent) * k)] =
                      codes[static_cast<std::size_t>(x.origin + i) +
                            static_cast<std::size_t>(full[0]) *
                                ((y.origin + j) + static_cast<std::size_t>(full[1]) * (z.origin + k))];
          }
          bricksOfGrid[gi].push_back(static_cast<int>(out.textures.size()));
          out.textures.push_back(std::move(t));
        }
  }
  for (std::size_t i = 0; i < grids.size(); ++i)
    if (grids[i].coefficient > 0)
      for (int b : bricksOfGrid[i]) out.passes.push_back({b, BlendEquation::FuncAdd});
  for (std::size_t i = 0; i < grids.size(); ++i)
    if (grids[i].coefficient < 0)
      for (int repeat = 0; repeat < (scaled ? 1 : 2); ++repeat)
        for (int b : bricksOfGrid[i]) out.passes.push_back({b, BlendEquation::FuncReverseSubtract});
  return out;
}

std::size_t textureBytes(const CombinationTextures& textures) {
  std::size_t bytes = 0;
  for (const GridTexture& t : textures.textures)
    bytes += t.codes.size() * static_cast<std::size_t>(bytesPerTexel(textures.format));
  return bytes;
}

}  // namespace voxref::ref
