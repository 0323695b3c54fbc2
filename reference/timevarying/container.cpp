#include "reference/timevarying/container.h"

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace voxref::ref {
namespace {

constexpr std::size_t kHeaderBytes = 96;
constexpr std::uint32_t kMaxExtent = 16384;

std::size_t channelBytes(IndexEncoding e) {
  return e == IndexEncoding::NormalizedRgba16 ? 2 : e == IndexEncoding::NormalizedFloat ? 4 : 1;
}

bool isPow2(std::uint64_t v) { return v && (v & (v - 1)) == 0; }

}  // namespace

std::string serializeTimeVarying(const TimeVaryingFile& f) {
  const TimeVaryingTextures& t = f.textures;
  const TimeVaryingLayout& L = t.layout;
  if (L.timeSteps < 1 || L.timeSteps > 65536)
    throw std::invalid_argument(std::to_string(L.timeSteps) +
                                " time steps: the .vxtv container holds 1..65536 (FORMAT.md, time_steps)");
  ByteWriter w;
  w.bytes("VXTV", 4);
  w.le<std::uint16_t>(1);
  w.le<std::uint16_t>(0);
  for (int v : {L.side, L.timeSteps, L.level, L.cells, L.blockSide, L.indexSlots, L.blockSlots, L.original[0],
                L.original[1], L.original[2]})
    w.le<std::uint32_t>(static_cast<std::uint32_t>(v));
  w.le<std::uint8_t>(static_cast<std::uint8_t>(t.index.encoding));
  w.le<std::uint8_t>(t.alphaOne == AlphaOnePolicy::Paper ? 0 : 1);
  w.le<std::uint16_t>(0);
  w.le<std::uint32_t>(static_cast<std::uint32_t>(t.stats.distinctBlocks));
  for (std::size_t v : {t.stats.homogeneousCells, t.stats.refinedCells, t.stats.hashHits, t.stats.hashCollisions,
                        t.stats.alphaOneCells})
    w.le<std::uint64_t>(v);
  w.le<std::uint8_t>(static_cast<std::uint8_t>(f.transfer.name.size()));
  w.bytes(f.transfer.name.data(), f.transfer.name.size());
  for (const Rgba8& c : f.transfer.table) w.bytes(c.data(), 4);
  const std::size_t cb = channelBytes(t.index.encoding);
  for (std::uint32_t v : t.index.texels)
    for (std::size_t i = 0; i < cb; ++i) w.le<std::uint8_t>(static_cast<std::uint8_t>(v >> (8 * i)));
  w.bytes(t.refinement.texels.data(), t.refinement.texels.size());
  const std::uint32_t c = crc32(w.str());
  w.le<std::uint32_t>(c);
  return std::move(w.str());
}

namespace {

TimeVaryingFile parse(std::string_view b) {
  ByteReader r(b);
  // Section 1: header.
  if (r.take(4, "magic") != std::string_view("VXTV", 4)) r.fail(0, "magic: expected 'VXTV' (not a .vxtv file)");
  if (const auto v = r.le<std::uint16_t>("version"); v != 1) r.fail(4, "version: expected 1, got " + std::to_string(v));
  if (const auto v = r.le<std::uint16_t>("flags"); v != 0) r.fail(6, "flags: expected 0, got " + std::to_string(v));
  TimeVaryingFile f;
  TimeVaryingLayout& L = f.textures.layout;
  auto u32 = [&](const char* field, std::uint32_t lo, std::uint32_t hi) {
    const std::size_t at = r.offset();
    const std::uint32_t v = r.le<std::uint32_t>(field);
    if (v < lo || v > hi)
      r.fail(at, std::string(field) + ": expected " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " +
                     std::to_string(v));
    return v;
  };
  L.side = static_cast<int>(u32("side", 4, 512));
  if (!isPow2(static_cast<std::uint64_t>(L.side)))
    r.fail(8, "side: expected a power of two, got " + std::to_string(L.side));
  L.timeSteps = static_cast<int>(u32("time_steps", 1, 65536));
  const int maxLevel = std::countr_zero(static_cast<unsigned>(L.side)) - 1;
  L.level = static_cast<int>(u32("level", 1, static_cast<std::uint32_t>(maxLevel)));
  L.cells = static_cast<int>(u32("cells", 1u << L.level, 1u << L.level));
  L.blockSide = static_cast<int>(
      u32("block_side", static_cast<std::uint32_t>(L.side / L.cells), static_cast<std::uint32_t>(L.side / L.cells)));
  L.indexSlots = static_cast<int>(u32("index_slots", 1, kMaxExtent / static_cast<std::uint32_t>(L.cells)));
  if (!isPow2(static_cast<std::uint64_t>(L.indexSlots)) ||
      static_cast<std::uint64_t>(L.indexSlots) * L.indexSlots * L.indexSlots < static_cast<std::uint64_t>(L.timeSteps))
    r.fail(28, "index_slots: expected a power of two S with S^3 >= " + std::to_string(L.timeSteps));
  L.blockSlots = static_cast<int>(u32("block_slots", 1, kMaxExtent / static_cast<std::uint32_t>(L.blockSide)));
  if (!isPow2(static_cast<std::uint64_t>(L.blockSlots))) r.fail(32, "block_slots: expected a power of two");
  for (int a = 0; a < 3; ++a)
    L.original[a] = static_cast<int>(u32("original extent", 1, static_cast<std::uint32_t>(L.side)));
  const std::size_t encodingAt = r.offset();
  const auto enc = r.le<std::uint8_t>("encoding");
  if (enc > 3) r.fail(encodingAt, "encoding: expected 0..3, got " + std::to_string(enc));
  f.textures.index.encoding = static_cast<IndexEncoding>(enc);
  if (f.textures.index.encoding == IndexEncoding::BlockRgba8 && L.blockSlots > 256)
    r.fail(32, "block_slots: block_rgba8 addresses at most 256 slots per axis");
  const auto policy = r.le<std::uint8_t>("alpha_one_policy");
  if (policy > 1) r.fail(encodingAt + 1, "alpha_one_policy: expected 0 or 1, got " + std::to_string(policy));
  f.textures.alphaOne = policy == 0 ? AlphaOnePolicy::Paper : AlphaOnePolicy::Refine;
  if (r.le<std::uint16_t>("reserved") != 0) r.fail(encodingAt + 2, "reserved: expected 0");
  const std::uint64_t blockCapacity = static_cast<std::uint64_t>(L.blockSlots) * L.blockSlots * L.blockSlots;
  const std::size_t distinctAt = r.offset();
  const std::uint64_t distinct = r.le<std::uint32_t>("distinct_blocks");
  if (distinct > blockCapacity)
    r.fail(distinctAt, "distinct_blocks: " + std::to_string(distinct) + " exceeds the " +
                           std::to_string(blockCapacity) + " block slots");
  EncodeStats& st = f.textures.stats;
  st.distinctBlocks = distinct;
  st.homogeneousCells = r.le<std::uint64_t>("homogeneous_cells");
  const std::size_t refinedAt = r.offset();
  st.refinedCells = r.le<std::uint64_t>("refined_cells");
  const std::uint64_t cellsTotal = static_cast<std::uint64_t>(L.timeSteps) * L.cells * L.cells * L.cells;
  if (st.homogeneousCells > cellsTotal || st.refinedCells != cellsTotal - st.homogeneousCells)
    r.fail(refinedAt, "refined_cells: homogeneous + refined must be " + std::to_string(cellsTotal));
  st.hashHits = r.le<std::uint64_t>("hash_hits");
  st.hashCollisions = r.le<std::uint64_t>("hash_collisions");
  st.alphaOneCells = r.le<std::uint64_t>("alpha_one_cells");

  // Section 2: transfer function.
  const std::size_t nameAt = r.offset();
  const auto nameLength = r.le<std::uint8_t>("transfer function name length");
  if (nameLength < 1 || nameLength > 64)
    r.fail(nameAt, "transfer function name length: expected 1..64, got " + std::to_string(nameLength));
  f.transfer.name = std::string(r.take(nameLength, "transfer function name"));
  const std::string_view table = r.take(1024, "transfer function table");
  for (int i = 0; i < 256; ++i)
    std::memcpy(f.transfer.table[static_cast<std::size_t>(i)].data(), table.data() + 4 * i, 4);

  // Sections 3 and 4: sizes are checked against the file before anything is allocated.
  const std::uint64_t indexSide = static_cast<std::uint64_t>(L.indexSlots) * L.cells;
  const std::uint64_t refSide = static_cast<std::uint64_t>(L.blockSlots) * L.blockSide;
  const std::size_t cb = channelBytes(f.textures.index.encoding);
  const std::uint64_t indexBytes = indexSide * indexSide * indexSide * 4 * cb;
  const std::uint64_t refBytes = refSide * refSide * refSide * 4;
  const std::uint64_t expectedTotal = r.offset() + indexBytes + refBytes + 4;
  if (expectedTotal != b.size())
    r.fail(r.offset(), "the header describes " + std::to_string(expectedTotal) + " bytes in all, the file has " +
                           std::to_string(b.size()) +
                           (b.size() < expectedTotal ? " (truncated)" : " (trailing bytes)"));
  const auto stored = static_cast<std::uint32_t>(loadLe(b.data() + b.size() - 4, 4));
  if (!crc32Matches(b.substr(0, b.size() - 4), stored))
    r.fail(b.size() - 4, "trailer: CRC-32 mismatch (the file is corrupt)");

  IndexTexture& index = f.textures.index;
  index.dims = {static_cast<int>(indexSide), static_cast<int>(indexSide), static_cast<int>(indexSide)};
  const std::size_t indexAt = r.offset();
  const std::string_view ib = r.take(static_cast<std::size_t>(indexBytes), "index texture");
  index.texels.resize(static_cast<std::size_t>(indexBytes / cb));
  for (std::size_t i = 0; i < index.texels.size(); ++i) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < cb; ++k)
      v |= static_cast<std::uint32_t>(static_cast<unsigned char>(ib[i * cb + k])) << (8 * k);
    index.texels[i] = v;
  }
  RefinementTexture& ref = f.textures.refinement;
  ref.dims = {static_cast<int>(refSide), static_cast<int>(refSide), static_cast<int>(refSide)};
  const std::string_view rb = r.take(static_cast<std::size_t>(refBytes), "refinement texture");
  ref.texels.assign(rb.begin(), rb.end());

  // Every refinement address must name one of the stored blocks; under the paper's policy a
  // flagged texel may be a colour, which the decoder reads as an address (FORMAT.md section 3).
  for (std::size_t texel = 0; texel < index.texels.size() / 4; ++texel) {
    const std::uint32_t* t = &index.texels[4 * texel];
    if (!isRefinementFlag(index.encoding, t)) continue;
    if (index.encoding == IndexEncoding::NormalizedFloat)
      for (int a = 0; a < 3; ++a) {
        const float v = std::bit_cast<float>(t[a]);
        if (!(v >= 0.0f && v <= 1.0f))
          r.fail(indexAt + texel * 4 * cb,
                 "index texel " + std::to_string(texel) + ": address is not a number in [0, 1]");
      }
    if (f.textures.alphaOne == AlphaOnePolicy::Paper) continue;
    const auto k = blockOfIndexTexel(L, index.encoding, t);
    const std::uint64_t slot =
        static_cast<std::uint64_t>(k[0]) +
        static_cast<std::uint64_t>(L.blockSlots) * (k[1] + static_cast<std::uint64_t>(L.blockSlots) * k[2]);
    if (k[0] >= L.blockSlots || k[1] >= L.blockSlots || k[2] >= L.blockSlots || slot >= distinct)
      r.fail(indexAt + texel * 4 * cb, "index texel " + std::to_string(texel) + ": refinement address (" +
                                           std::to_string(k[0]) + ", " + std::to_string(k[1]) + ", " +
                                           std::to_string(k[2]) + ") is not one of the " + std::to_string(distinct) +
                                           " blocks");
  }
  st.indexBytes = static_cast<std::size_t>(L.timeSteps) * L.cells * L.cells * L.cells * 4 * cb;
  st.refinementBytes = static_cast<std::size_t>(distinct) * L.blockSide * L.blockSide * L.blockSide * 4;
  st.indexBytesAllocated = static_cast<std::size_t>(indexBytes);
  st.refinementBytesAllocated = static_cast<std::size_t>(refBytes);
  st.inputVoxels = static_cast<std::size_t>(L.timeSteps) * sampleCount(L.original);
  return f;
}

}  // namespace

TimeVaryingFile parseTimeVarying(std::string_view b) { return parse(b); }

}  // namespace voxref::ref
