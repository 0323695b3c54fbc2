#include "reference/leb/leb_codec.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"
#include "reference/common/parallel.h"
#include "reference/leb/gradients.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/leb_page.h"
#include "reference/leb/prediction.h"

namespace voxref::ref {
namespace {

struct ChannelSpec {
  LebChannelKind kind;
  int components, valueBits;
  bool isSigned;
};

ChannelSpec specOf(LebChannelKind kind, int sampleBits) {
  return kind == LebChannelKind::Data ? ChannelSpec{kind, 1, sampleBits, false} : ChannelSpec{kind, 3, 8, true};
}
ChannelSpec specOf(const LebChannel& c) { return {c.kind, c.components, c.valueBits, c.isSigned}; }

// The values of a channel on the whole grid, as raw bit patterns (16 bits hold both 16-bit
// samples and int8 gradient components), stored in bricks of 8^3 points: the split-edge
// endpoints of the fine levels (most points) lie in the same brick as the point, where a
// row-major grid would put them a slice apart.
struct GridValues {
  GridValues(const LebGrid& grid, const ChannelSpec& s) : spec(s), bricksPerAxis((grid.pointsPerAxis() + 7) / 8) {
    const auto b = static_cast<std::uint64_t>(bricksPerAxis);
    raw.assign(b * b * b * 512 * static_cast<std::uint64_t>(spec.components), 0);
  }
  std::uint64_t slot(const GridPoint& p) const {
    const auto b = static_cast<std::uint64_t>(bricksPerAxis);
    const std::uint64_t brick = static_cast<std::uint64_t>(p[0] >> 3) +
                                b * (static_cast<std::uint64_t>(p[1] >> 3) + b * static_cast<std::uint64_t>(p[2] >> 3));
    return brick * 512 + static_cast<std::uint64_t>((p[0] & 7) | (p[1] & 7) << 3 | (p[2] & 7) << 6);
  }
  std::int32_t load(std::uint64_t at, int c) const {
    return wrapSample(raw[at * static_cast<std::uint64_t>(spec.components) + static_cast<std::uint64_t>(c)],
                      spec.valueBits, spec.isSigned);
  }
  void store(std::uint64_t at, int c, std::int32_t v) {
    raw[at * static_cast<std::uint64_t>(spec.components) + static_cast<std::uint64_t>(c)] =
        static_cast<std::uint16_t>(v);
  }
  ChannelSpec spec;
  int bricksPerAxis;
  std::vector<std::uint16_t> raw;
};

// The walk both the encoder and the decoder make (section 3.1, steps 2-4 of the reconstruction):
// points in hierarchical order from `begin` to `end`, each predicted from its split edge, which
// the walk has already passed. For a point inside the volume valueOf(h, volumeIndex, component,
// prediction) gives its value (the encoder reads the sample and records the delta; the decoder
// reads the delta and adds it); a point of the padding takes its prediction.
template <class ValueOf>
void walkPredictions(const HzOrder& order, const Dims3& dims, GridValues& g, std::uint64_t begin, std::uint64_t end,
                     ValueOf&& valueOf) {
  const int comps = g.spec.components;
  for (HzCursor c(order, begin); c.index() < end; c.next()) {
    const GridPoint& p = c.point();
    std::int32_t pred[3] = {0, 0, 0};
    if (c.level() >= 0) {
      const SplitEdge e = splitEdgeOf(p, c.scaleLog2(), c.oddAxes());
      const std::uint64_t ia = g.slot(e.a), ib = g.slot(e.b);
      for (int k = 0; k < comps; ++k) pred[k] = predictMidpoint(g.load(ia, k), g.load(ib, k));
    }
    const std::uint64_t gi = g.slot(p);
    if (insideVolume(p, dims)) {
      const std::size_t vi = static_cast<std::size_t>(p[0]) +
                             static_cast<std::size_t>(dims[0]) *
                                 (static_cast<std::size_t>(p[1]) + static_cast<std::size_t>(dims[1]) * p[2]);
      for (int k = 0; k < comps; ++k) g.store(gi, k, valueOf(c.index(), vi, k, pred[k]));
    } else {
      for (int k = 0; k < comps; ++k) g.store(gi, k, pred[k]);
    }
  }
}

// All deltas of a channel in stream order, and where each page's deltas begin.
struct ChannelDeltas {
  std::vector<std::int32_t> deltas;
  std::vector<std::size_t> pageStart;  // pages + 1 entries
};

template <class Sample>
ChannelDeltas predictChannel(const HzOrder& order, const Dims3& dims, const ChannelSpec& spec, int pageBits,
                             Sample&& sample) {
  GridValues g(order.grid(), spec);
  ChannelDeltas out;
  const std::uint64_t perPage = std::uint64_t{1} << pageBits;
  const std::uint64_t pages = (order.size() + perPage - 1) / perPage;
  out.deltas.reserve(static_cast<std::size_t>(sampleCount(dims)) * static_cast<std::size_t>(spec.components));
  for (std::uint64_t page = 0; page < pages; ++page) {
    out.pageStart.push_back(out.deltas.size());
    walkPredictions(order, dims, g, page * perPage, std::min(order.size(), (page + 1) * perPage),
                    [&](std::uint64_t, std::size_t vi, int k, std::int32_t pred) {
                      const std::int32_t v = sample(vi, k);
                      out.deltas.push_back(predictionDelta(v, pred, spec.valueBits));
                      return v;
                    });
  }
  out.pageStart.push_back(out.deltas.size());
  return out;
}

ChannelDeltas predictChannelOf(const HzOrder& order, const Volume<std::uint16_t>& volume, const ChannelSpec& spec,
                               int pageBits) {
  if (spec.kind == LebChannelKind::Data)
    return predictChannel(order, volume.dims(), spec, pageBits,
                          [&](std::size_t vi, int) { return static_cast<std::int32_t>(volume.data()[vi]); });
  const std::vector<std::int8_t> grads = quantizedGradients(volume);
  return predictChannel(order, volume.dims(), spec, pageBits, [&](std::size_t vi, int k) {
    return static_cast<std::int32_t>(grads[3 * vi + static_cast<std::size_t>(k)]);
  });
}

void checkPageBits(int pageBits) {
  if (pageBits < kMinLebPageBits || pageBits > kMaxLebPageBits)
    throw std::invalid_argument("page bits must be in " + std::to_string(kMinLebPageBits) + ".." +
                                std::to_string(kMaxLebPageBits) + ", got " + std::to_string(pageBits));
}

void checkSamples(const Volume<std::uint16_t>& volume, int sampleBits) {
  if (sampleBits != 8 && sampleBits != 16)
    throw std::invalid_argument("sample bits must be 8 or 16, got " + std::to_string(sampleBits));
  const std::uint32_t limit = 1u << sampleBits;
  const auto& d = volume.data();
  const auto it = std::find_if(d.begin(), d.end(), [&](std::uint16_t v) { return v >= limit; });
  if (it != d.end())
    throw std::invalid_argument("sample " + std::to_string(it - d.begin()) + " is " + std::to_string(*it) + ", not a " +
                                std::to_string(sampleBits) + "-bit value");
}

}  // namespace

std::string encodeLeb(const Volume<std::uint16_t>& volume, int sampleBits, const LebEncodeOptions& o) {
  checkSamples(volume, sampleBits);
  checkPageBits(o.pageBits);
  const LebGrid grid = lebGridCovering(volume.dims());
  const HzOrder order(grid);
  std::vector<LebChannelPayload> channels;
  std::vector<LebChannelKind> kinds{LebChannelKind::Data};
  if (o.gradients) kinds.push_back(LebChannelKind::Gradients);
  for (LebChannelKind kind : kinds) {
    const ChannelSpec spec = specOf(kind, sampleBits);
    const ChannelDeltas d = predictChannelOf(order, volume, spec, o.pageBits);
    const std::size_t pages = d.pageStart.size() - 1;
    auto pageDeltas = [&](std::size_t p) {
      return std::span<const std::int32_t>(d.deltas).subspan(d.pageStart[p], d.pageStart[p + 1] - d.pageStart[p]);
    };
    Lead1Counter counter(spec.valueBits);
    for (std::size_t p = 0; p < pages; ++p) counter.add(pageDeltas(p));
    LebChannelPayload c{kind,          spec.components, spec.valueBits,
                        spec.isSigned, counter.code(),  std::vector<std::string>(pages)};
    const Lead1Encoder encoder(c.code);
    parallelFor(static_cast<int>(pages), o.threads, [&](int p) {
      BitWriter w;
      encoder.encodePage(pageDeltas(static_cast<std::size_t>(p)), w);
      c.pages[static_cast<std::size_t>(p)] = w.finish();
    });
    channels.push_back(std::move(c));
  }
  return serializeLebStream(volume.dims(), sampleBits, grid, o.pageBits, channels);
}

std::uint64_t lebEncodeMemoryBytes(const Dims3& dims, const LebEncodeOptions& o) {
  checkPageBits(o.pageBits);
  const LebGrid grid = lebGridCovering(dims);
  const auto samples =
      static_cast<std::uint64_t>(dims[0]) * static_cast<std::uint64_t>(dims[1]) * static_cast<std::uint64_t>(dims[2]);
  const auto bricks = static_cast<std::uint64_t>((grid.pointsPerAxis() + 7) / 8);
  const auto points = static_cast<std::uint64_t>(grid.pointsPerAxis());
  const std::uint64_t pages = (points * points * points + (std::uint64_t{1} << o.pageBits) - 1) >> o.pageBits;
  // A coded value takes at most kMaxCodeLength + 17 magnitude and sign bits < 4 bytes
  // (lead1_coder.h); each page adds a flush byte and its std::string.
  auto coded = [&](int components) { return 4 * samples * static_cast<std::uint64_t>(components) + pages * 64; };
  std::uint64_t peak = 0, pagesSoFar = 0;
  for (const int components : o.gradients ? std::vector<int>{1, 3} : std::vector<int>{1}) {
    const std::uint64_t gridBytes =
        bricks * bricks * bricks * 512 * static_cast<std::uint64_t>(components) * 2;  // GridValues
    const std::uint64_t gradients = components == 3 ? 3 * samples : 0;
    peak = std::max(peak, gridBytes + 4 * samples * static_cast<std::uint64_t>(components) + gradients + pagesSoFar +
                              coded(components));
    pagesSoFar += coded(components);
  }
  return std::max(peak, 2 * pagesSoFar);  // serializing: the pages and the stream they make
}

std::uint64_t lebDecodeMemoryBytes(const LebStream& s) {
  const auto samples = static_cast<std::uint64_t>(s.dims[0]) * static_cast<std::uint64_t>(s.dims[1]) *
                       static_cast<std::uint64_t>(s.dims[2]);
  const auto bricks = static_cast<std::uint64_t>((s.grid.pointsPerAxis() + 7) / 8);
  std::uint64_t bytes = 2 * samples, grid = 0;
  for (const LebChannel& c : s.channels) {
    if (c.kind == LebChannelKind::Gradients) bytes += 3 * samples;
    grid = std::max(grid, bricks * bricks * bricks * 512 * static_cast<std::uint64_t>(c.components) * 2);  // GridValues
  }
  return bytes + grid;
}

LebDecoded decodeLeb(const LebStream& s, int threads) {
  const HzOrder order(s.grid);
  LebDecoded out;
  out.data = Volume<std::uint16_t>(s.dims);
  const int pb = s.pageBits;
  for (const LebChannel& ch : s.channels) {
    const ChannelSpec spec = specOf(ch);
    if (ch.kind == LebChannelKind::Gradients) out.gradients.assign(3 * sampleCount(s.dims), 0);
    GridValues g(s.grid, spec);
    // Level by level: the points of one level depend only on coarser ones, so the parts of the
    // level's pages are reconstructed in parallel; a page's reader carries on where the previous
    // level left it, and is finished (its padding checked) once the walk has left the page.
    std::map<std::uint64_t, Lead1PageReader> open;
    for (int level = -1; level < s.grid.levelCount(); ++level) {
      const std::uint64_t begin = order.levelBegin(level), end = order.levelBegin(level + 1);
      if (begin == end) continue;
      const std::uint64_t first = begin >> pb, last = (end - 1) >> pb;
      for (std::uint64_t p = first; p <= last; ++p)
        if (!open.count(p)) open.emplace(p, openPage(s, ch, p));
      parallelFor(static_cast<int>(last - first + 1), threads, [&](int i) {
        const std::uint64_t page = first + static_cast<std::uint64_t>(i);
        Lead1PageReader& reader = open.at(page);
        walkPredictions(order, s.dims, g, std::max(begin, page << pb), std::min(end, (page + 1) << pb),
                        [&](std::uint64_t, std::size_t vi, int k, std::int32_t pred) {
                          const std::int32_t v = reconstructSample(pred, reader.next(), spec.valueBits, spec.isSigned);
                          if (ch.kind == LebChannelKind::Data)
                            out.data.data()[vi] = static_cast<std::uint16_t>(v);
                          else
                            out.gradients[3 * vi + static_cast<std::size_t>(k)] = static_cast<std::int8_t>(v);
                          return v;
                        });
      });
      const bool lastLevel = level + 1 == s.grid.levelCount();
      for (auto it = open.begin(); it != open.end() && (it->first < last || lastLevel);) {
        it->second.finish();
        it = open.erase(it);
      }
    }
  }
  return out;
}

std::vector<std::int32_t> lebDeltas(const Volume<std::uint16_t>& volume, int sampleBits, LebChannelKind kind) {
  checkSamples(volume, sampleBits);
  const HzOrder order(lebGridCovering(volume.dims()));
  return predictChannelOf(order, volume, specOf(kind, sampleBits), kMaxLebPageBits).deltas;
}

double LebStats::ratio() const {
  std::uint64_t raw = 0;
  for (const LebChannelStats& c : channels) raw += c.rawBytes;
  return static_cast<double>(raw) / static_cast<double>(streamBytes);
}

double LebStats::channelRatio(LebChannelKind kind) const {
  for (const LebChannelStats& c : channels)
    if (c.kind == kind)
      return static_cast<double>(c.rawBytes) /
             static_cast<double>(c.compressedBytes() + (kind == LebChannelKind::Data ? headerBytes : 0));
  return 0.0;
}

LebStats lebStats(const LebStream& s) {
  LebStats st;
  st.dims = s.dims;
  st.sampleBits = s.sampleBits;
  st.k = s.grid.k;
  st.pageBits = s.pageBits;
  st.gridPoints = s.grid.pointCount();
  st.volumePoints = sampleCount(s.dims);
  st.pages = s.pageCount();
  st.headerBytes = kLebHeaderBytes;
  st.streamBytes = s.bytes.size();
  for (const LebChannel& c : s.channels) {
    LebChannelStats cs;
    cs.kind = c.kind;
    cs.rawBytes =
        st.volumePoints * static_cast<std::uint64_t>(c.components) * static_cast<std::uint64_t>(c.valueBits / 8);
    cs.descriptorBytes = c.descriptorBytes;
    cs.payloadBytes = c.payloadBytes();
    cs.codedValues = st.volumePoints * static_cast<std::uint64_t>(c.components);
    st.channels.push_back(cs);
  }
  return st;
}

}  // namespace voxref::ref
