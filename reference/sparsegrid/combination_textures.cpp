#include "reference/sparsegrid/combination_textures.h"

#include <cmath>

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

double textureCoordinate(double p, int level, int extent) { return (std::ldexp(p, level) + 0.5) / extent; }

CombinationTextures buildCombinationTextures(const Combination& combination, const CombinationTextureOptions& options) {
  CombinationTextures out;
  out.format = options.format;
  out.sizing = options.sizing;
  out.scaling = options.scaling;
  out.positiveCount = combination.positiveCount();
  const bool scaled = options.scaling == ScalingPolicy::Scaled;
  out.readbackScale = scaled ? combination.positiveCount() : 1.0;
  const std::uint32_t zeroCode = encodeTexel(options.format, 0.0);
  for (const ComponentGrid& g : combination.grids()) {
    GridTexture t;
    t.levels = g.levels;
    for (int a = 0; a < 3; ++a) t.dims[a] = textureExtent(g.levels[a], options.sizing);
    t.codes.assign(sampleCount(t.dims), zeroCode);
    // dataToTexture: t = f / n+ * d(node); negative grids carry f = 2 (pseudo code, section 6).
    const double factor = scaled ? (g.coefficient < 0 ? 2.0 : 1.0) : 1.0;
    const auto& d = g.values.dims();
    for (int z = 0; z < d[2]; ++z)
      for (int y = 0; y < d[1]; ++y)
        for (int x = 0; x < d[0]; ++x) {
          const double v = scaled ? factor * g.values.at(x, y, z) / combination.positiveCount() : g.values.at(x, y, z);
          t.codes[static_cast<std::size_t>(x) + static_cast<std::size_t>(t.dims[0]) * (y + static_cast<std::size_t>(t.dims[1]) * z)] =
              encodeTexel(options.format, v);
        }
    out.textures.push_back(std::move(t));
  }
  const auto& grids = combination.grids();
  for (std::size_t i = 0; i < grids.size(); ++i)
    if (grids[i].coefficient > 0) out.passes.push_back({static_cast<int>(i), BlendEquation::FuncAdd});
  for (std::size_t i = 0; i < grids.size(); ++i)
    if (grids[i].coefficient < 0)
      for (int repeat = 0; repeat < (scaled ? 1 : 2); ++repeat)
        out.passes.push_back({static_cast<int>(i), BlendEquation::FuncReverseSubtract});
  return out;
}

std::size_t textureBytes(const CombinationTextures& textures) {
  std::size_t bytes = 0;
  for (const GridTexture& t : textures.textures) bytes += t.codes.size() * static_cast<std::size_t>(bytesPerTexel(textures.format));
  return bytes;
}

}  // namespace voxref::ref
