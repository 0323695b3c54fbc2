#include "reference/timevarying/timevarying_codec.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <unordered_map>

#include "reference/common/rounding.h"

namespace voxref::ref {
namespace {

int ceilPow2(int v) {
  int p = 1;
  while (p < v) p <<= 1;
  return p;
}

// Smallest power of two S with S^3 >= count (count >= 1).
int cubeSlots(std::size_t count) {
  int s = 1;
  while (static_cast<std::size_t>(s) * s * s < std::max<std::size_t>(count, 1)) s <<= 1;
  return s;
}

std::uint64_t fnv1a(const std::uint8_t* p, std::size_t n) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}

std::uint32_t maxCode(IndexEncoding e) {
  switch (e) {
    case IndexEncoding::NormalizedRgba16:
      return 65535;
    case IndexEncoding::NormalizedFloat:
      return std::bit_cast<std::uint32_t>(1.0f);
    default:
      return 255;
  }
}

// Index texel channels for a homogeneous colour.
std::array<std::uint32_t, 4> colourTexel(IndexEncoding e, const Rgba8& c) {
  std::array<std::uint32_t, 4> out{};
  for (int ch = 0; ch < 4; ++ch) switch (e) {
      case IndexEncoding::NormalizedRgba16:
        out[ch] = 257u * c[ch];
        break;  // k/255 == 257k/65535 exactly
      case IndexEncoding::NormalizedFloat:
        out[ch] = std::bit_cast<std::uint32_t>(static_cast<float>(c[ch] / 255.0));
        break;
      default:
        out[ch] = c[ch];
    }
  return out;
}

// Index texel channels for a refinement address of block slot coordinates `k`.
std::array<std::uint32_t, 4> addressTexel(IndexEncoding e, int blockSlots, const std::array<int, 3>& k) {
  std::array<std::uint32_t, 4> out{};
  for (int a = 0; a < 3; ++a) {
    // The normalized origin k / B (exact: B is a power of two), stored as GL converts floats to
    // unorm: correctly rounded, half to even (rounding.h).
    const double v = static_cast<double>(k[a]) / blockSlots;
    switch (e) {
      case IndexEncoding::NormalizedRgba8:
        out[a] = unormFromDouble(v, 8);
        break;
      case IndexEncoding::NormalizedRgba16:
        out[a] = unormFromDouble(v, 16);
        break;
      case IndexEncoding::NormalizedFloat:
        out[a] = std::bit_cast<std::uint32_t>(static_cast<float>(v));
        break;  // dyadic: exact
      case IndexEncoding::BlockRgba8:
        out[a] = static_cast<std::uint32_t>(k[a]);
        break;
    }
  }
  out[3] = maxCode(e);
  return out;
}

}  // namespace

std::string_view name(IndexEncoding e) {
  switch (e) {
    case IndexEncoding::NormalizedRgba8:
      return "normalized_rgba8";
    case IndexEncoding::NormalizedRgba16:
      return "normalized_rgba16";
    case IndexEncoding::NormalizedFloat:
      return "normalized_float";
    case IndexEncoding::BlockRgba8:
      return "block_rgba8";
  }
  return "?";
}

std::optional<IndexEncoding> parseIndexEncoding(std::string_view s) {
  for (IndexEncoding e : {IndexEncoding::NormalizedRgba8, IndexEncoding::NormalizedRgba16,
                          IndexEncoding::NormalizedFloat, IndexEncoding::BlockRgba8})
    if (name(e) == s) return e;
  return std::nullopt;
}

TimeSeries padToCube(const std::vector<Volume<std::uint8_t>>& volumes, std::uint8_t padValue) {
  if (volumes.empty()) throw std::invalid_argument("a time series needs at least one time step");
  const Dims3 dims = volumes.front().dims();
  for (std::size_t t = 0; t < volumes.size(); ++t)
    if (volumes[t].dims() != dims)
      throw std::invalid_argument("time step " + std::to_string(t) + " has other extents than time step 0");
  for (int e : dims)
    if (e > 512) throw std::invalid_argument("extent " + std::to_string(e) + " exceeds 512");
  TimeSeries s;
  s.side = std::max(4, ceilPow2(std::max({dims[0], dims[1], dims[2]})));
  s.original = dims;
  const std::size_t n = static_cast<std::size_t>(s.side) * s.side * s.side;
  for (const auto& v : volumes) {
    std::vector<std::uint8_t> cube(n, padValue);
    for (int z = 0; z < dims[2]; ++z)
      for (int y = 0; y < dims[1]; ++y)
        std::memcpy(&cube[static_cast<std::size_t>(s.side) * (y + static_cast<std::size_t>(s.side) * z)],
                    &v.at(0, y, z), static_cast<std::size_t>(dims[0]));
    s.steps.push_back(std::move(cube));
  }
  return s;
}

std::array<int, 3> indexSlot(const TimeVaryingLayout& l, int t) {
  return {t % l.indexSlots, (t / l.indexSlots) % l.indexSlots, t / (l.indexSlots * l.indexSlots)};
}

std::array<int, 3> blockSlot(const TimeVaryingLayout& l, int k) {
  return {k % l.blockSlots, (k / l.blockSlots) % l.blockSlots, k / (l.blockSlots * l.blockSlots)};
}

std::array<int, 3> paperIndexOrigin(int t, int di, int dr) {
  return {(t % di) * dr, (t / di) * dr, (t % (di * di)) * dr};
}

TimeVaryingTextures encodeTimeVarying(const TimeSeries& series, const TransferFunction& tf,
                                      const TimeVaryingOptions& o) {
  const int side = series.side;
  if (series.steps.empty()) throw std::invalid_argument("a time series needs at least one time step");
  if (side < 4 || (side & (side - 1)) != 0) throw std::invalid_argument("the volume side must be a power of two >= 4");
  const int maxLevel = std::countr_zero(static_cast<unsigned>(side)) - 1;
  if (o.level < 1 || o.level > maxLevel)
    throw std::invalid_argument("subdivision level " + std::to_string(o.level) + " is outside 1.." +
                                std::to_string(maxLevel) + " for " + std::to_string(side) + "^3 volumes");
  TimeVaryingTextures out;
  out.alphaOne = o.alphaOne;
  TimeVaryingLayout& L = out.layout;
  L.side = side;
  L.timeSteps = static_cast<int>(series.steps.size());
  L.level = o.level;
  L.cells = 1 << o.level;
  L.blockSide = side / L.cells;
  L.indexSlots = o.paperLayout ? side / L.cells : cubeSlots(series.steps.size());
  if (o.paperLayout && static_cast<std::size_t>(L.indexSlots) * L.indexSlots * L.indexSlots < series.steps.size())
    throw CapacityError("the paper's " + std::to_string(side) + "^3 index texture holds " +
                        std::to_string(L.indexSlots * L.indexSlots * L.indexSlots) + " time steps at level " +
                        std::to_string(o.level) + ", got " + std::to_string(series.steps.size()));
  L.original = series.original;
  if (L.indexSlots * L.cells > o.maxTextureExtent)
    throw CapacityError("the index texture would need " + std::to_string(L.indexSlots * L.cells) +
                        " texels per axis for " + std::to_string(L.timeSteps) + " time steps; the limit is " +
                        std::to_string(o.maxTextureExtent));
  const int r = L.blockSide;
  const std::size_t blockVoxels = static_cast<std::size_t>(r) * r * r;
  const std::uint64_t hashMask = o.hashBits >= 64 ? ~0ull : ((1ull << o.hashBits) - 1ull);

  // Pass 1: classify every cell, deduplicate the blocks (by their scalars).
  std::vector<std::vector<std::uint8_t>> blocks;
  std::unordered_map<std::uint64_t, std::vector<int>> byHash;
  std::vector<int> cellBlock(static_cast<std::size_t>(L.timeSteps) * L.cells * L.cells * L.cells, -1);
  std::vector<std::uint8_t> cellValue(cellBlock.size(), 0);
  std::vector<std::uint8_t> block(blockVoxels);
  std::size_t cellIndex = 0;
  for (int t = 0; t < L.timeSteps; ++t) {
    const std::vector<std::uint8_t>& vol = series.steps[static_cast<std::size_t>(t)];
    for (int cz = 0; cz < L.cells; ++cz)
      for (int cy = 0; cy < L.cells; ++cy)
        for (int cx = 0; cx < L.cells; ++cx, ++cellIndex) {
          std::size_t i = 0;
          for (int z = 0; z < r; ++z)
            for (int y = 0; y < r; ++y) {
              const std::uint8_t* row =
                  &vol[static_cast<std::size_t>(cx * r) +
                       static_cast<std::size_t>(side) * ((cy * r + y) + static_cast<std::size_t>(side) * (cz * r + z))];
              std::memcpy(&block[i], row, static_cast<std::size_t>(r));
              i += static_cast<std::size_t>(r);
            }
          const bool homogeneous =
              std::all_of(block.begin(), block.end(), [&](std::uint8_t v) { return v == block[0]; });
          if (homogeneous && tf(block[0])[3] == 255) ++out.stats.alphaOneCells;
          if (homogeneous && (tf(block[0])[3] != 255 || o.alphaOne == AlphaOnePolicy::Paper)) {
            ++out.stats.homogeneousCells;
            cellValue[cellIndex] = block[0];
            continue;
          }
          ++out.stats.refinedCells;
          const std::uint64_t h = fnv1a(block.data(), blockVoxels) & hashMask;
          std::vector<int>& candidates = byHash[h];
          int found = -1;
          for (int c : candidates) {
            if (std::memcmp(blocks[static_cast<std::size_t>(c)].data(), block.data(), blockVoxels) == 0) {
              found = c;
              break;
            }
            ++out.stats.hashCollisions;  // same hash, different voxels: the full comparison caught it
          }
          if (found >= 0) {
            ++out.stats.hashHits;
          } else {
            found = static_cast<int>(blocks.size());
            blocks.push_back(block);
            candidates.push_back(found);
          }
          cellBlock[cellIndex] = found;
        }
  }
  out.stats.distinctBlocks = blocks.size();
  L.blockSlots = o.paperLayout ? L.cells : cubeSlots(blocks.size());
  if (o.paperLayout && blocks.size() > static_cast<std::size_t>(L.cells) * L.cells * L.cells)
    throw CapacityError("the paper's " + std::to_string(side) + "^3 refinement texture holds " +
                        std::to_string(L.cells * L.cells * L.cells) + " blocks at level " + std::to_string(o.level) +
                        ", the data needs " + std::to_string(blocks.size()));
  if (L.blockSlots * r > o.maxTextureExtent)
    throw CapacityError("the refinement texture would need " + std::to_string(L.blockSlots * r) +
                        " texels per axis for " + std::to_string(blocks.size()) + " blocks of " + std::to_string(r) +
                        "^3; the limit is " + std::to_string(o.maxTextureExtent));
  if (o.encoding == IndexEncoding::BlockRgba8 && L.blockSlots > 256)
    throw CapacityError("block_rgba8 addresses at most 256 block slots per axis; " + std::to_string(blocks.size()) +
                        " blocks need " + std::to_string(L.blockSlots));

  // Pass 2: the textures.
  out.index.encoding = o.encoding;
  out.index.dims = {L.indexSlots * L.cells, L.indexSlots * L.cells, L.indexSlots * L.cells};
  out.index.texels.assign(sampleCount(out.index.dims) * 4, 0);
  cellIndex = 0;
  for (int t = 0; t < L.timeSteps; ++t) {
    const auto slot = indexSlot(L, t);
    for (int cz = 0; cz < L.cells; ++cz)
      for (int cy = 0; cy < L.cells; ++cy)
        for (int cx = 0; cx < L.cells; ++cx, ++cellIndex) {
          const int b = cellBlock[cellIndex];
          const auto texel = b < 0 ? colourTexel(o.encoding, tf(cellValue[cellIndex]))
                                   : addressTexel(o.encoding, L.blockSlots, blockSlot(L, b));
          const std::size_t at = 4 * (static_cast<std::size_t>(slot[0] * L.cells + cx) +
                                      static_cast<std::size_t>(out.index.dims[0]) *
                                          (static_cast<std::size_t>(slot[1] * L.cells + cy) +
                                           static_cast<std::size_t>(out.index.dims[1]) * (slot[2] * L.cells + cz)));
          std::copy(texel.begin(), texel.end(), out.index.texels.begin() + static_cast<std::ptrdiff_t>(at));
        }
  }
  out.refinement.dims = {L.blockSlots * r, L.blockSlots * r, L.blockSlots * r};
  out.refinement.texels.assign(sampleCount(out.refinement.dims) * 4, 0);
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const auto s = blockSlot(L, static_cast<int>(k));
    std::size_t i = 0;
    for (int z = 0; z < r; ++z)
      for (int y = 0; y < r; ++y)
        for (int x = 0; x < r; ++x, ++i) {
          const Rgba8& c = tf(blocks[k][i]);
          const std::size_t at = 4 * (static_cast<std::size_t>(s[0] * r + x) +
                                      static_cast<std::size_t>(out.refinement.dims[0]) *
                                          (static_cast<std::size_t>(s[1] * r + y) +
                                           static_cast<std::size_t>(out.refinement.dims[1]) * (s[2] * r + z)));
          std::copy(c.begin(), c.end(), out.refinement.texels.begin() + static_cast<std::ptrdiff_t>(at));
        }
  }
  const std::size_t channelBytes = o.encoding == IndexEncoding::NormalizedRgba16  ? 2
                                   : o.encoding == IndexEncoding::NormalizedFloat ? 4
                                                                                  : 1;
  out.stats.indexBytes = static_cast<std::size_t>(L.timeSteps) * L.cells * L.cells * L.cells * 4 * channelBytes;
  out.stats.refinementBytes = blocks.size() * blockVoxels * 4;
  out.stats.indexBytesAllocated = sampleCount(out.index.dims) * 4 * channelBytes;
  out.stats.refinementBytesAllocated = sampleCount(out.refinement.dims) * 4;
  out.stats.inputVoxels = static_cast<std::size_t>(L.timeSteps) * sampleCount(series.original);  // padding excluded
  return out;
}

TimeVaryingTextures encodeTimeVaryingAutoLevel(const TimeSeries& series, const TransferFunction& tf,
                                               TimeVaryingOptions options) {
  std::optional<TimeVaryingTextures> best;
  std::string lastError;
  const int maxLevel = std::countr_zero(static_cast<unsigned>(series.side)) - 1;
  for (int level = 1; level <= maxLevel; ++level) {
    options.level = level;
    try {
      TimeVaryingTextures t = encodeTimeVarying(series, tf, options);
      // The textures as allocated are what a file stores (the .vxtv container keeps whole
      // textures): the fewest allocated bytes make the smallest file.
      const auto bytes = [](const TimeVaryingTextures& x) {
        return x.stats.indexBytesAllocated + x.stats.refinementBytesAllocated;
      };
      if (!best || bytes(t) < bytes(*best)) best = std::move(t);
    } catch (const CapacityError& e) {
      lastError = e.what();
    }
  }
  if (!best) throw CapacityError("no subdivision level fits the texture limits: " + lastError);
  return std::move(*best);
}

bool isRefinementFlag(IndexEncoding e, const std::uint32_t* texel) { return texel[3] == maxCode(e); }

std::array<int, 3> blockOfIndexTexel(const TimeVaryingLayout& L, IndexEncoding e, const std::uint32_t* texel) {
  std::array<int, 3> k{};
  const std::int64_t B = L.blockSlots;
  for (int a = 0; a < 3; ++a) {
    const std::int64_t c = texel[a];
    switch (e) {
      case IndexEncoding::NormalizedRgba8:
        k[a] = static_cast<int>((2 * c * B + 255) / 510);
        break;  // round(c B / 255)
      case IndexEncoding::NormalizedRgba16:
        k[a] = static_cast<int>((2 * c * B + 65535) / 131070);
        break;  // round(c B / 65535)
      case IndexEncoding::NormalizedFloat:
        k[a] = static_cast<int>(std::llround(static_cast<double>(std::bit_cast<float>(texel[a])) * B));
        break;
      case IndexEncoding::BlockRgba8:
        k[a] = static_cast<int>(c);
        break;
    }
  }
  return k;
}

Rgba8 colourOfIndexTexel(IndexEncoding e, const std::uint32_t* texel) {
  Rgba8 c{};
  for (int ch = 0; ch < 4; ++ch) switch (e) {
      case IndexEncoding::NormalizedRgba16:
        c[ch] = static_cast<std::uint8_t>(texel[ch] / 257u);
        break;
      case IndexEncoding::NormalizedFloat:
        c[ch] = static_cast<std::uint8_t>(std::lround(std::bit_cast<float>(texel[ch]) * 255.0));
        break;
      default:
        c[ch] = static_cast<std::uint8_t>(texel[ch]);
    }
  return c;
}

VoxelAddress addressOfVoxel(const TimeVaryingTextures& tex, int t, int x, int y, int z) {
  const TimeVaryingLayout& L = tex.layout;
  if (t < 0 || t >= L.timeSteps || x < 0 || y < 0 || z < 0 || x >= L.side || y >= L.side || z >= L.side)
    throw std::out_of_range("voxel (" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) +
                            ") of step " + std::to_string(t) + " is outside the series");
  const int r = L.blockSide;
  const auto slot = indexSlot(L, t);
  VoxelAddress a;
  a.indexTexel = {slot[0] * L.cells + x / r, slot[1] * L.cells + y / r, slot[2] * L.cells + z / r};
  const std::uint32_t* texel =
      &tex.index.texels[4 * (static_cast<std::size_t>(a.indexTexel[0]) +
                             static_cast<std::size_t>(tex.index.dims[0]) *
                                 (a.indexTexel[1] + static_cast<std::size_t>(tex.index.dims[1]) * a.indexTexel[2]))];
  a.refined = isRefinementFlag(tex.index.encoding, texel);
  if (!a.refined) return a;
  const auto k = blockOfIndexTexel(L, tex.index.encoding, texel);
  a.refinementTexel = {k[0] * r + x % r, k[1] * r + y % r, k[2] * r + z % r};
  for (int i = 0; i < 3; ++i)
    if (k[i] < 0 || a.refinementTexel[i] >= tex.refinement.dims[i])
      throw std::out_of_range("index texel of step " + std::to_string(t) + " addresses block slot (" +
                              std::to_string(k[0]) + ", " + std::to_string(k[1]) + ", " + std::to_string(k[2]) +
                              ") outside the refinement texture");
  return a;
}

namespace {

// The refinement texel the paper's decoder reads for a flagged index texel whose stored address
// lies past the refinement texture: clamped to the last texel per axis (CLAMP_TO_EDGE).
VoxelAddress clampedPaperAddress(const TimeVaryingTextures& tex, int t, int x, int y, int z) {
  const TimeVaryingLayout& L = tex.layout;
  VoxelAddress a;
  const int r = L.blockSide;
  const auto slot = indexSlot(L, t);
  a.indexTexel = {slot[0] * L.cells + x / r, slot[1] * L.cells + y / r, slot[2] * L.cells + z / r};
  const std::uint32_t* texel =
      &tex.index.texels[4 * (static_cast<std::size_t>(a.indexTexel[0]) +
                             static_cast<std::size_t>(tex.index.dims[0]) *
                                 (a.indexTexel[1] + static_cast<std::size_t>(tex.index.dims[1]) * a.indexTexel[2]))];
  a.refined = true;
  const auto k = blockOfIndexTexel(L, tex.index.encoding, texel);
  const int within[3] = {x % r, y % r, z % r};
  for (int i = 0; i < 3; ++i) a.refinementTexel[i] = std::clamp(k[i] * r + within[i], 0, tex.refinement.dims[i] - 1);
  return a;
}

}  // namespace

Rgba8 decodeVoxel(const TimeVaryingTextures& tex, int t, int x, int y, int z) {
  VoxelAddress a;
  try {
    a = addressOfVoxel(tex, t, x, y, z);
  } catch (const std::out_of_range&) {
    // Coordinates outside the series are refused again by addressOfVoxel; a colour read as an
    // address past the texture is what the paper's policy stores.
    if (tex.alphaOne != AlphaOnePolicy::Paper || t < 0 || t >= tex.layout.timeSteps || x < 0 || y < 0 || z < 0 ||
        x >= tex.layout.side || y >= tex.layout.side || z >= tex.layout.side || tex.refinement.texels.empty())
      throw;
    a = clampedPaperAddress(tex, t, x, y, z);
  }
  if (!a.refined) {
    const auto& it = a.indexTexel;
    return colourOfIndexTexel(
        tex.index.encoding, &tex.index.texels[4 * (static_cast<std::size_t>(it[0]) +
                                                   static_cast<std::size_t>(tex.index.dims[0]) *
                                                       (it[1] + static_cast<std::size_t>(tex.index.dims[1]) * it[2]))]);
  }
  const auto& v = a.refinementTexel;
  const std::uint8_t* c =
      &tex.refinement.texels[4 * (static_cast<std::size_t>(v[0]) +
                                  static_cast<std::size_t>(tex.refinement.dims[0]) *
                                      (v[1] + static_cast<std::size_t>(tex.refinement.dims[1]) * v[2]))];
  return {c[0], c[1], c[2], c[3]};
}

std::vector<Rgba8> decodeStep(const TimeVaryingTextures& tex, int t) {
  const Dims3 d = tex.layout.original;
  std::vector<Rgba8> out(sampleCount(d));
  std::size_t i = 0;
  for (int z = 0; z < d[2]; ++z)
    for (int y = 0; y < d[1]; ++y)
      for (int x = 0; x < d[0]; ++x) out[i++] = decodeVoxel(tex, t, x, y, z);
  return out;
}

}  // namespace voxref::ref
