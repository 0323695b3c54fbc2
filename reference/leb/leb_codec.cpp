#include "reference/leb/leb_codec.h"

#include <algorithm>
#include <map>
#include <memory>
#include <stdexcept>

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"
#include "reference/common/parallel.h"
#include "reference/leb/gradients.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/leb_padding.h"
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

// The values of a channel at its points inside the volume (the samples, or their gradients, in
// volume order) as the predictor reads them.
struct InsideValues {
  const std::uint16_t* data = nullptr;  // data channel
  const std::int8_t* gradients = nullptr;
  std::int32_t operator()(std::size_t vi, int k) const {
    return data ? static_cast<std::int32_t>(data[vi])
                : static_cast<std::int32_t>(gradients[3 * vi + static_cast<std::size_t>(k)]);
  }
};

// The walk both the encoder and the decoder make (section 3.1, steps 2-4 of the reconstruction):
// the points inside the volume with index in [begin, end), in hierarchical order, each predicted
// from its split edge (endpoints inside the volume from `inside`, in the padding from the shell,
// leb_padding.h); valueOf(vi, component, prediction) gives its value (the encoder reads the sample
// and records the delta; the decoder reads the delta and writes the sample).
//
// A point whose split-edge endpoints both lie inside the volume (all but the points next to the
// padding) reads them at volume indices vi + off and vi - off: on every odd axis the edge runs
// sigma = +-h from p (splitEdgeSigma), so off = sum of sigma_a * stride_a. read(vi, k) is component k
// of `inside`, with the component count fixed at compile time.
template <int Components, class Read, class ValueOf>
void walkChannel(const HzOrder& order, const Dims3& dims, const LebPadding& padding, const InsideValues& inside,
                 Read&& read, std::uint64_t begin, std::uint64_t end, ValueOf&& valueOf) {
  const std::ptrdiff_t stride[3] = {1, dims[0], static_cast<std::ptrdiff_t>(dims[0]) * dims[1]};
  order.forEachInside(
      dims, begin, end, [&](std::uint64_t h, const GridPoint& p, int level, int scaleLog2, unsigned odd) {
        const std::size_t vi = volumeIndex(p, dims);
        LebValues pred{0, 0, 0};
        if (level >= 0) {
          const int step = 1 << scaleLog2;
          std::ptrdiff_t off = 0;
          bool within = true;
          for (int a = 0; a < 3; ++a)
            if ((odd >> a) & 1u) {
              within = within && p[a] + step < dims[a];
              off += splitEdgeSigma(p, scaleLog2, a) * stride[a];
            }
          if (within) {
            const auto a = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(vi) + off);
            const auto b = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(vi) - off);
            for (int k = 0; k < Components; ++k)
              pred[static_cast<std::size_t>(k)] = predictMidpoint(read(a, k), read(b, k));
          } else {
            pred = predictPoint(p, level, scaleLog2, odd, Components,
                                [&](const GridPoint& q, int k) { return padding.valueAt(q, k, inside); });
          }
        }
        for (int k = 0; k < Components; ++k) valueOf(h, vi, k, pred[static_cast<std::size_t>(k)]);
      });
}

template <class ValueOf>
void walkInside(const HzOrder& order, const Dims3& dims, const LebPadding& padding, const InsideValues& inside,
                int components, std::uint64_t begin, std::uint64_t end, ValueOf&& valueOf) {
  if (components == 1)
    walkChannel<1>(
        order, dims, padding, inside, [&](std::size_t vi, int) { return static_cast<std::int32_t>(inside.data[vi]); },
        begin, end, valueOf);
  else
    walkChannel<3>(
        order, dims, padding, inside,
        [&](std::size_t vi, int k) {
          return static_cast<std::int32_t>(inside.gradients[3 * vi + static_cast<std::size_t>(k)]);
        },
        begin, end, valueOf);
}

// The deltas of a run of pages, per stored page (the pages that hold a point of the volume).
struct RunDeltas {
  std::vector<std::uint32_t> storedPage;
  std::vector<std::vector<std::int32_t>> pages;
};

// Pages in runs of this many, one run per task: the runs, not the thread count, fix the work.
constexpr std::uint64_t kPagesPerRun = 64;
std::uint64_t runsOf(std::uint64_t pages) { return (pages + kPagesPerRun - 1) / kPagesPerRun; }

// The prediction of one channel over the grid, run by run: the shell of the padding first (it
// needs only the volume), then any run's deltas on demand, independently of the others.
class ChannelPrediction {
 public:
  ChannelPrediction(const HzOrder& order, const Dims3& dims, const ChannelSpec& spec, int pageBits,
                    const InsideValues& inside)
      : order_(order),
        dims_(dims),
        spec_(spec),
        pageBits_(pageBits),
        inside_(inside),
        padding_(order.grid(), dims, spec.components) {
    for (int level = -1; level < order.grid().levelCount(); ++level) padding_.addLevel(level, inside);
  }
  std::uint64_t runs() const { return runsOf(lebPageCount(order_.grid(), pageBits_)); }
  RunDeltas run(std::uint64_t r) const {
    RunDeltas out;
    const std::uint64_t first = r * kPagesPerRun;
    walkInside(order_, dims_, padding_, inside_, spec_.components, first << pageBits_,
               (first + kPagesPerRun) << pageBits_, [&](std::uint64_t h, std::size_t vi, int k, std::int32_t pred) {
                 const auto page = static_cast<std::uint32_t>(h >> pageBits_);
                 if (out.storedPage.empty() || out.storedPage.back() != page) {
                   out.storedPage.push_back(page);
                   out.pages.emplace_back();
                 }
                 out.pages.back().push_back(predictionDelta(inside_(vi, k), pred, spec_.valueBits));
               });
    return out;
  }

 private:
  const HzOrder& order_;
  Dims3 dims_;
  ChannelSpec spec_;
  int pageBits_;
  InsideValues inside_;
  LebPadding padding_;
};

// One channel's payload in two passes over the runs, so that no more than one run's deltas per
// thread are ever held: the counts for the code (section 3.1: one code for all pages), then the
// deltas again, each page coded as soon as it is predicted.
LebChannelPayload encodeChannel(const HzOrder& order, const Dims3& dims, const ChannelSpec& spec, int pageBits,
                                const InsideValues& inside, int threads) {
  const ChannelPrediction prediction(order, dims, spec, pageBits, inside);
  const int runs = static_cast<int>(prediction.runs());
  std::vector<std::unique_ptr<Lead1Counter>> counters(static_cast<std::size_t>(runs));  // runs with a stored page
  parallelFor(runs, threads, [&](int r) {
    for (const auto& page : prediction.run(static_cast<std::uint64_t>(r)).pages) {
      auto& counter = counters[static_cast<std::size_t>(r)];
      if (!counter) counter = std::make_unique<Lead1Counter>(spec.valueBits);
      counter->add(page);
    }
  });
  Lead1Counter counter(spec.valueBits);
  for (const auto& c : counters)
    if (c) counter.merge(*c);
  LebChannelPayload c{spec.kind, spec.components, spec.valueBits, spec.isSigned, counter.code(), {}, {}};
  const Lead1Encoder encoder(c.code);
  std::vector<std::vector<std::uint32_t>> stored(static_cast<std::size_t>(runs));  // per run, its stored pages
  std::vector<std::vector<std::string>> bytes(static_cast<std::size_t>(runs));     // and their codes
  parallelFor(runs, threads, [&](int r) {
    RunDeltas d = prediction.run(static_cast<std::uint64_t>(r));
    for (const auto& page : d.pages) {
      BitWriter w;
      encoder.encodePage(page, w);
      bytes[static_cast<std::size_t>(r)].push_back(w.finish());
    }
    stored[static_cast<std::size_t>(r)] = std::move(d.storedPage);
  });
  for (std::size_t r = 0; r < stored.size(); ++r) {
    c.storedPage.insert(c.storedPage.end(), stored[r].begin(), stored[r].end());
    for (std::string& page : bytes[r]) c.pages.push_back(std::move(page));
  }
  return c;
}

// The inside values of a channel of `volume` (the gradients computed into `gradients`).
InsideValues insideOf(const Volume<std::uint16_t>& volume, LebChannelKind kind, std::vector<std::int8_t>& gradients) {
  if (kind == LebChannelKind::Data) return InsideValues{volume.data().data(), nullptr};
  gradients = quantizedGradients(volume);
  return InsideValues{nullptr, gradients.data()};
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
    std::vector<std::int8_t> gradients;
    const InsideValues inside = insideOf(volume, kind, gradients);
    channels.push_back(encodeChannel(order, volume.dims(), specOf(kind, sampleBits), o.pageBits, inside, o.threads));
  }
  return serializeLebStream(volume.dims(), sampleBits, grid, o.pageBits, channels);
}

std::uint64_t lebEncodeMemoryBytes(const Dims3& dims, const LebEncodeOptions& o) {
  checkPageBits(o.pageBits);
  const LebGrid grid = lebGridCovering(dims);
  const auto samples =
      static_cast<std::uint64_t>(dims[0]) * static_cast<std::uint64_t>(dims[1]) * static_cast<std::uint64_t>(dims[2]);
  const std::uint64_t perPage = std::uint64_t{1} << o.pageBits;
  const std::uint64_t pages = lebPageCount(grid, o.pageBits);
  const std::uint64_t stored = std::min(pages, samples);  // a stored page holds a point of the volume
  const std::uint64_t shell = LebPadding::shellPoints(grid, dims) * LebPadding::kBytesPerPoint;
  // In flight: one run's deltas per worker (4 bytes a value) and the runs' counters.
  const std::uint64_t workers = static_cast<std::uint64_t>(workerCount(o.threads));
  const std::uint64_t runs = runsOf(pages);
  auto inFlight = [&](int components) {
    return workers * std::min(samples, kPagesPerRun * perPage) * static_cast<std::uint64_t>(components) * 4 +
           runs * 88 + std::min(runs, samples) * (17 * 17 * 8 + 64);
  };
  // A coded value takes at most kMaxCodeLength + 17 magnitude and sign bits < 4 bytes
  // (lead1_coder.h); each stored page adds a flush byte and its std::string.
  auto coded = [&](int components) { return 4 * samples * static_cast<std::uint64_t>(components) + stored * 64; };
  std::uint64_t peak = 0, pagesSoFar = 0;
  for (const int components : o.gradients ? std::vector<int>{1, 3} : std::vector<int>{1}) {
    const std::uint64_t gradients = components == 3 ? 3 * samples : 0;
    peak = std::max(peak, shell + inFlight(components) + gradients + pagesSoFar + coded(components));
    pagesSoFar += coded(components);
  }
  return std::max(peak, 2 * pagesSoFar);  // serializing: the pages and the stream they make
}

std::uint64_t lebDecodeMemoryBytes(const LebStream& s) {
  const std::uint64_t samples = sampleCount(s.dims);
  std::uint64_t bytes = 2 * samples;
  for (const LebChannel& c : s.channels)
    if (c.kind == LebChannelKind::Gradients) bytes += 3 * samples;
  return bytes + LebPadding::shellPoints(s.grid, s.dims) * LebPadding::kBytesPerPoint;  // one channel's shell at a time
}

LebDecoded decodeLeb(const LebStream& s, int threads) {
  const HzOrder order(s.grid);
  LebDecoded out;
  out.data = Volume<std::uint16_t>(s.dims);
  const int pb = s.pageBits;
  for (const LebChannel& ch : s.channels) {
    const ChannelSpec spec = specOf(ch);
    const bool data = ch.kind == LebChannelKind::Data;
    if (!data) out.gradients.assign(3 * sampleCount(s.dims), 0);
    const InsideValues inside{data ? out.data.data().data() : nullptr, data ? nullptr : out.gradients.data()};
    LebPadding padding(s.grid, s.dims, spec.components);
    // Level by level: the points of one level depend only on coarser ones, so the level's part of
    // each stored page is reconstructed in parallel; a page's reader carries on where the previous
    // level left it, and is finished (its end checked) once the walk has left the page. Between
    // stored pages, the walk checks that no point of the volume lies in a page the stream lacks.
    std::map<std::uint64_t, Lead1PageReader> open;
    for (int level = -1; level < s.grid.levelCount(); ++level) {
      padding.addLevel(level, inside);
      const std::uint64_t begin = order.levelBegin(level), end = order.levelBegin(level + 1);
      if (begin == end) continue;
      // Segments of the level: a stored page's part of it, or a run of pages the stream lacks.
      struct Segment {
        std::uint64_t begin, end;
        Lead1PageReader* reader;
      };
      std::vector<Segment> segments;
      auto stored = std::lower_bound(ch.storedPage.begin(), ch.storedPage.end(), begin >> pb);
      for (std::uint64_t at = begin; at < end;) {
        if (stored != ch.storedPage.end() && (std::uint64_t{*stored} << pb) < end) {
          const std::uint64_t page = *stored, pageBegin = std::max(begin, page << pb);
          if (at < pageBegin) segments.push_back({at, pageBegin, nullptr});
          auto it = open.find(page);
          if (it == open.end()) it = open.emplace(page, openPage(s, ch, page)).first;
          at = std::min(end, (page + 1) << pb);
          segments.push_back({pageBegin, at, &it->second});
          ++stored;
        } else {
          segments.push_back({at, end, nullptr});
          at = end;
        }
      }
      parallelFor(static_cast<int>(segments.size()), threads, [&](int i) {
        const Segment& seg = segments[static_cast<std::size_t>(i)];
        walkInside(order, s.dims, padding, inside, spec.components, seg.begin, seg.end,
                   [&](std::uint64_t h, std::size_t vi, int k, std::int32_t pred) {
                     if (!seg.reader) throw pageNotStored(ch, h >> pb);
                     const std::int32_t v = reconstructSample(pred, seg.reader->next(), spec.valueBits, spec.isSigned);
                     if (data)
                       out.data.data()[vi] = static_cast<std::uint16_t>(v);
                     else
                       out.gradients[3 * vi + static_cast<std::size_t>(k)] = static_cast<std::int8_t>(v);
                   });
      });
      for (auto it = open.begin(); it != open.end() && std::min(order.size(), (it->first + 1) << pb) <= end;) {
        finishPage(it->second, it->second.valuesRead() / static_cast<std::size_t>(spec.components), ch, it->first);
        it = open.erase(it);
      }
    }
    if (!open.empty()) throw std::logic_error("LEB decode: a page outlived the grid");
  }
  return out;
}

std::vector<std::int32_t> lebDeltas(const Volume<std::uint16_t>& volume, int sampleBits, LebChannelKind kind) {
  checkSamples(volume, sampleBits);
  const HzOrder order(lebGridCovering(volume.dims()));
  std::vector<std::int8_t> gradients;
  const ChannelPrediction prediction(order, volume.dims(), specOf(kind, sampleBits), kMaxLebPageBits,
                                     insideOf(volume, kind, gradients));
  std::vector<std::int32_t> deltas;
  for (std::uint64_t r = 0; r < prediction.runs(); ++r)
    for (const auto& page : prediction.run(r).pages) deltas.insert(deltas.end(), page.begin(), page.end());
  return deltas;
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
  st.storedPages = s.channels.empty() ? 0 : s.channels.front().storedPage.size();
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
