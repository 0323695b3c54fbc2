#include "reference/leb/leb_codec.h"

#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <vector>

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"
#include "reference/common/parallel.h"
#include "reference/leb/adaptive_delta_coder.h"
#include "reference/leb/context_codec.h"
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

// Calls f with the channel's values in a volume span: the samples (withLebSamples), or the gradients
// (3 int8 components a sample), in volume order.
template <class Span, class F>
void withChannel(const Span& v, LebChannelKind kind, F&& f) {
  if (kind == LebChannelKind::Gradients)
    f(v.gradients);
  else
    withLebSamples(v, f);
}

// The components of a channel stored as T: the gradients are its only signed type
// (parseLebStream admits no other channel).
template <class T>
constexpr int componentsOf() {
  return std::is_signed_v<T> ? 3 : 1;
}

// The values of a channel at its points inside the volume as the predictor reads them: exactly
// one pointer is set.
struct InsideValues {
  const std::uint8_t* data8 = nullptr;
  const std::uint16_t* data16 = nullptr;
  const std::int8_t* gradients = nullptr;
  std::int32_t operator()(std::size_t vi, int k) const {
    if (data8) return static_cast<std::int32_t>(data8[vi]);
    if (data16) return static_cast<std::int32_t>(data16[vi]);
    return static_cast<std::int32_t>(gradients[3 * vi + static_cast<std::size_t>(k)]);
  }
  template <class F>
  void visit(F&& f) const {
    withChannel(*this, gradients ? LebChannelKind::Gradients : LebChannelKind::Data, f);
  }
};

template <class Span>
InsideValues insideOf(const Span& v, LebChannelKind kind) {
  InsideValues r;
  withChannel(v, kind, [&](auto* p) {
    using T = std::remove_cv_t<std::remove_pointer_t<decltype(p)>>;
    if constexpr (std::is_same_v<T, std::uint8_t>)
      r.data8 = p;
    else if constexpr (std::is_same_v<T, std::uint16_t>)
      r.data16 = p;
    else
      r.gradients = p;
  });
  return r;
}

// The prediction's components of the point at volume index vi of `values` (componentsOf<T> a
// point) from its split edge's endpoints vi +- off, both inside the volume.
template <class T>
void predictBetween(const T* values, std::size_t vi, std::ptrdiff_t off, std::int32_t* pred) {
  constexpr int K = componentsOf<T>();
  const T* a = values + K * static_cast<std::size_t>(static_cast<std::ptrdiff_t>(vi) + off);
  const T* b = values + K * static_cast<std::size_t>(static_cast<std::ptrdiff_t>(vi) - off);
  for (int k = 0; k < K; ++k) pred[k] = predictMidpoint(a[k], b[k]);
}

// The values one channel's predictions read: `values` (those of `inside`, as their type, whose
// component count is fixed at compile time) and the channel's shell of the padding.
template <class T>
struct ChannelValues {
  static constexpr int kValues = componentsOf<T>();  // predictions a point
  const T* values;
  const LebPadding& padding;
  const InsideValues& inside;
  // The prediction's components from the split edge's endpoints vi +- off, both inside the volume.
  void between(std::size_t vi, std::ptrdiff_t off, std::int32_t* pred) const { predictBetween(values, vi, off, pred); }
  // The prediction of p (of `level`, scale 2^scaleLog2, odd axes `odd`) whose split edge reaches
  // the padding.
  void onShell(const GridPoint& p, int level, int scaleLog2, unsigned odd, std::int32_t* pred) const {
    const LebValues v = predictPoint(p, level, scaleLog2, odd, kValues,
                                     [&](const GridPoint& q) { return padding.valuesAt(q, inside); });
    std::copy_n(v.begin(), kValues, pred);
  }
};

// A stream's data and gradients predicted in one walk (the whole-volume decoder): a point's
// sample first, then its gradient's three components.
template <class D>
struct SampleAndGradientValues {
  static constexpr int kValues = 4;
  ChannelValues<D> data;
  ChannelValues<std::int8_t> gradients;
  void between(std::size_t vi, std::ptrdiff_t off, std::int32_t* pred) const {
    data.between(vi, off, pred);
    gradients.between(vi, off, pred + 1);
  }
  void onShell(const GridPoint& p, int level, int scaleLog2, unsigned odd, std::int32_t* pred) const {
    data.onShell(p, level, scaleLog2, odd, pred);
    gradients.onShell(p, level, scaleLog2, odd, pred + 1);
  }
};

// The walk both the encoder and the decoder make (section 3.1, steps 2-4 of the reconstruction):
// the points inside the volume with index in [begin, end), in hierarchical order, each predicted
// from its split edge (endpoints inside the volume from `inside`, in the padding from the shell,
// leb_padding.h) by `channels` (ChannelValues, or SampleAndGradientValues: Channels::kValues
// predictions a point). pointsOf(h, vi, pred, n) takes n points at once: those with indices h,
// h + 1, ..., h + n - 1, at volume indices vi[0..n), their predictions pred[kValues q + k] (the
// encoder reads the samples and records the deltas; the decoder reads the deltas and writes the
// samples). The points of one call are of one level, whose predictions read only coarser ones, so
// a consumer may take them in any order.
//
// A point whose split-edge endpoints both lie inside the volume (all but the points next to the
// padding) reads them at volume indices vi + off and vi - off: on every odd axis the edge runs
// sigma = +-h from p (splitEdgeSigma), so off = sum of sigma_a * stride_a.
//
// The range is walked level by level. A level's part whose points all lie inside the volume
// (HzOrder::allInside: nearly every page of a volume) goes by groups of cells
// (HzOrder::forEachCellInside), with the per-point work cut down (issue 18, goal 3): a point's
// volume index and its edge's offset lie at the same offsets from its group's corner in every group
// of a block, so they come from tables made at the block's first group; a group whose split edges
// all lie inside the volume (its far cells' far edges do) is predicted without a check per point,
// the others check each point, and a group's points are handed over in one call. The other parts
// go a point at a time (HzOrder::forEachInside). The same points in the same order, with the same
// predictions, either way. A consumer with a member within(h, base, pointOffset, edgeOffset, n)
// takes the groups whose edges lie inside the volume as their tables instead: point q at volume
// index base + pointOffset[q], its edge's endpoints at +- edgeOffset[q] (the decoder predicts and
// stores each point in one step, without the arrays between them).
template <class Channels, class PointsOf>
void walkPoints(const HzOrder& order, const Dims3& dims, const Channels& channels, std::uint64_t begin,
                std::uint64_t end, PointsOf&& pointsOf) {
  constexpr int Components = Channels::kValues;
  const std::ptrdiff_t stride[3] = {1, dims[0], static_cast<std::ptrdiff_t>(dims[0]) * dims[1]};
  // The prediction of point p of a level (not a root corner) at volume index vi, whose split edge's
  // endpoints lie at vi +- off where they are inside the volume: between them where both are (the
  // far one is p + h on every odd axis), else from the shell.
  auto predictAt = [&](const GridPoint& p, std::size_t vi, std::ptrdiff_t off, int level, int scaleLog2, unsigned odd,
                       std::int32_t* pred) {
    bool edgeInside = true;
    for (int a = 0; a < 3; ++a) edgeInside = edgeInside && (!((odd >> a) & 1u) || p[a] + (1 << scaleLog2) < dims[a]);
    if (edgeInside)
      channels.between(vi, off, pred);
    else
      channels.onShell(p, level, scaleLog2, odd, pred);
  };
  auto atPoint = [&](std::uint64_t h, const GridPoint& p, int level, int scaleLog2, unsigned odd) {
    const std::size_t vi = volumeIndex(p, dims);
    std::int32_t pred[Components] = {};
    if (level >= 0) {
      std::ptrdiff_t off = 0;
      for (int a = 0; a < 3; ++a)
        if ((odd >> a) & 1u) off += splitEdgeSigma(p, scaleLog2, a) * stride[a];
      predictAt(p, vi, off, level, scaleLog2, odd, pred);
    }
    pointsOf(h, &vi, pred, 1);
  };
  auto byPoints = [&](std::uint64_t from, std::uint64_t to) { order.forEachInside(dims, from, to, atPoint); };
  auto byGroups = [&](std::uint64_t from, std::uint64_t to) {
    int key = -1;  // the block the tables are made for, at its first group
    // By the point's number q in a group: its place from the group's corner (grid and volume
    // index) and its split edge's offset.
    GridPoint place[HzOrder::CellGroup::kMaxPoints];
    std::ptrdiff_t pointOffset[HzOrder::CellGroup::kMaxPoints], edgeOffset[HzOrder::CellGroup::kMaxPoints];
    order.forEachCellInside(dims, from, to, [&](const HzOrder::CellGroup& g) {
      const int h = 1 << g.scaleLog2;
      if (g.blockKey != key) {
        key = g.blockKey;
        for (int q = 0; q < g.fullPoints; ++q) {
          const int cell = q / g.orientations;
          const unsigned odd = g.odd[q % g.orientations];
          GridPoint p = g.base;
          for (int i = 0; i < g.freeAxes; ++i) p[static_cast<std::size_t>(g.axis[i])] += ((cell >> i) & 1) * 2 * h;
          pointOffset[q] = edgeOffset[q] = 0;
          for (int a = 0; a < 3; ++a) {
            if ((odd >> a) & 1u) {
              p[a] += h;
              edgeOffset[q] += splitEdgeSigma(p, g.scaleLog2, a) * stride[a];
            }
            place[q][a] = p[a] - g.base[a];
            pointOffset[q] += place[q][a] * stride[a];
          }
        }
      }
      // Whether the group's far cells' far edges lie inside the volume: then so do all its
      // points' split edges, and no point needs its own check.
      bool within = true;
      for (int i = 0; i < g.freeAxes; ++i) {
        const auto a = static_cast<std::size_t>(g.axis[i]);
        within = within && g.base[a] + 4 * h < dims[a];
      }
      const std::ptrdiff_t baseIndex = g.base[0] + g.base[1] * stride[1] + g.base[2] * stride[2];
      if constexpr (requires { pointsOf.within(g.h, baseIndex, pointOffset, edgeOffset, 0); }) {
        if (within) [[likely]] {
          pointsOf.within(g.h, baseIndex, pointOffset + g.first, edgeOffset + g.first, g.last - g.first);
          return;
        }
      }
      std::size_t vi[HzOrder::CellGroup::kMaxPoints];
      std::int32_t pred[HzOrder::CellGroup::kMaxPoints * Components];
      int n = 0;
      if (within) [[likely]] {
        for (int q = g.first; q < g.last; ++q, ++n) {
          vi[n] = static_cast<std::size_t>(baseIndex + pointOffset[q]);
          channels.between(vi[n], edgeOffset[q], pred + Components * n);
        }
      } else {
        for (int q = g.first; q < g.last; ++q, ++n) {
          vi[n] = static_cast<std::size_t>(baseIndex + pointOffset[q]);
          const GridPoint p{g.base[0] + place[q][0], g.base[1] + place[q][1], g.base[2] + place[q][2]};
          predictAt(p, vi[n], edgeOffset[q], g.level, g.scaleLog2, g.odd[q % g.orientations], pred + Components * n);
        }
      }
      pointsOf(g.h, vi, pred, n);
    });
  };
  end = std::min(end, order.size());  // a run of pages may reach past the grid's last index
  int level = -1;
  for (std::uint64_t from = begin; from < end;) {
    while (order.levelBegin(level + 1) <= from) ++level;
    const std::uint64_t to = std::min(end, order.levelBegin(level + 1));
    if (level >= 0 && order.allInside(dims, from, to))
      byGroups(from, to);
    else
      byPoints(from, to);
    from = to;
  }
}

// walkPoints of one channel a value at a time: valueOf(h, vi, component, prediction), in index order.
template <class ValueOf>
void walkInside(const HzOrder& order, const Dims3& dims, const LebPadding& padding, const InsideValues& inside,
                std::uint64_t begin, std::uint64_t end, ValueOf&& valueOf) {
  inside.visit([&](const auto* values) {
    using T = std::remove_cv_t<std::remove_pointer_t<decltype(values)>>;
    constexpr int Components = componentsOf<T>();
    walkPoints(order, dims, ChannelValues<T>{values, padding, inside}, begin, end,
               [&](std::uint64_t h, const std::size_t* vi, const std::int32_t* pred, int n) {
                 for (int q = 0; q < n; ++q)
                   for (int k = 0; k < Components; ++k)
                     valueOf(h + static_cast<std::uint64_t>(q), vi[q], k, pred[Components * q + k]);
               });
  });
}

// The deltas of one segment of a page (a level's part of it, indices [begin, end)), decoded whole
// before its walk: `values` of them, the segment's points inside the volume times the components.
struct SegmentDeltas {
  LebPageReader* reader = nullptr;
  std::uint64_t begin = 0, end = 0;
  std::size_t values = 0;
  std::unique_ptr<std::int32_t[]> storage;
  void allocate(LebPageReader& from, std::uint64_t first, std::uint64_t last, std::uint64_t count) {
    reader = &from;
    begin = first;
    end = last;
    values = static_cast<std::size_t>(count);
    storage = std::make_unique_for_overwrite<std::int32_t[]>(values);
  }
  std::span<std::int32_t> deltas() const { return {storage.get(), values}; }
};

// reconstructSample's sum modulo 2^b (b = valueBits), as the output type T takes it: the samples
// unsigned by their mask, in 8 or 16 bits; the gradients 8-bit two's complement in int8 (the
// conversion, C++20 [conv.integral]).
template <class T>
T storedValue(std::int32_t sum, std::uint32_t mask) {
  if constexpr (std::is_signed_v<T>)
    return static_cast<T>(sum);
  else
    return static_cast<T>(static_cast<std::uint32_t>(sum) & mask);
}

// One channel's part in the reconstruction of a segment: its output, the segment's deltas
// (decoded whole) and how many of them the walk has taken.
template <class T>
struct ChannelStore {
  static constexpr int kComponents = componentsOf<T>();
  T* target;
  std::uint32_t mask;  // of the channel's b-bit values (storedValue)
  std::span<const std::int32_t> all;
  std::size_t taken = 0;
  // The deltas of the walk's next n points.
  const std::int32_t* take(int n) {
    const std::size_t values = kComponents * static_cast<std::size_t>(n);
    if (values > all.size() - taken) throw std::logic_error("LEB decode: the walk met more points than countInside");
    taken += values;
    return all.data() + (taken - values);
  }
  // The point at volume index vi of out: its prediction plus its delta, as the output type takes
  // the sum. A store through the output (a character type) may alias anything, so the callers'
  // loops hold what they keep in locals (out, m), and a point's components are summed before any
  // is stored: otherwise they would be loaded again after each store.
  static void storePoint(T* out, std::uint32_t m, std::size_t vi, const std::int32_t* pred, const std::int32_t* delta) {
    std::array<T, kComponents> sum;
    for (std::size_t c = 0; c < sum.size(); ++c) sum[c] = storedValue<T>(pred[c] + delta[c], m);
    std::copy_n(sum.data(), kComponents, out + kComponents * vi);
  }
  // The n points at volume indices vi[q], each one's prediction at pred + predStride q, their
  // deltas the next n kComponents of delta.
  void store(int n, const std::size_t* vi, const std::int32_t* pred, int predStride, const std::int32_t* delta) const {
    T* const out = target;
    const std::uint32_t m = mask;
    for (int q = 0; q < n; ++q, pred += predStride, delta += kComponents) storePoint(out, m, vi[q], pred, delta);
  }
  // The same for the n points of a group whose split edges lie inside the volume (walkPoints'
  // within): point q at volume index base + pointOffset[q], predicted from its edge's endpoints at
  // +- edgeOffset[q] in the target itself, which holds the coarser points (the decoder's
  // predictions read its outputs: withSegment).
  void storeWithin(int n, std::ptrdiff_t base, const std::ptrdiff_t* pointOffset, const std::ptrdiff_t* edgeOffset) {
    T* const out = target;
    const std::uint32_t m = mask;
    const std::int32_t* delta = take(n);
    for (int q = 0; q < n; ++q, delta += kComponents) {
      const auto vi = static_cast<std::size_t>(base + pointOffset[q]);
      std::int32_t pred[kComponents];
      predictBetween(out, vi, edgeOffset[q], pred);
      storePoint(out, m, vi, pred, delta);
    }
  }
  void finish() const {
    if (taken != all.size()) throw std::logic_error("LEB decode: the walk met fewer points than countInside");
  }
};

// What the walk of a segment hands its points to (walkPoints' pointsOf): each point's prediction
// plus its delta, stored by the channels' stores (in the order of the channels' predictions).
template <class Channels, class... Stores>
struct SegmentStores {
  std::tuple<Stores&...> stores;
  void operator()(std::uint64_t, const std::size_t* vi, const std::int32_t* pred, int n) {
    std::apply(
        [&](auto&... s) {
          int at = 0;  // the channel's first prediction of a point
          ((s.store(n, vi, pred + at, Channels::kValues, s.take(n)), at += std::decay_t<decltype(s)>::kComponents),
           ...);
        },
        stores);
  }
  void within(std::uint64_t, std::ptrdiff_t base, const std::ptrdiff_t* pointOffset, const std::ptrdiff_t* edgeOffset,
              int n) {
    std::apply([&](auto&... s) { (s.storeWithin(n, base, pointOffset, edgeOffset), ...); }, stores);
  }
};

// Writes the values of the segment [begin, end) of each channel that `stores` holds (in the order
// of `channels`' predictions): each point's prediction plus its delta, in the walk's order.
template <class Channels, class... Stores>
void reconstructSegment(const HzOrder& order, const Dims3& dims, const Channels& channels, std::uint64_t begin,
                        std::uint64_t end, Stores&... stores) {
  walkPoints(order, dims, channels, begin, end, SegmentStores<Channels, Stores...>{{stores...}});
  (stores.finish(), ...);
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
    walkInside(order_, dims_, padding_, inside_, first << pageBits_, (first + kPagesPerRun) << pageBits_,
               [&](std::uint64_t h, std::size_t vi, int k, std::int32_t pred) {
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

// The part [base, base + span) of the work that a pass takes, for the window's fraction.
struct WorkSpan {
  double base = 0.0, span = 1.0;
};

// A few items a worker: what the encoder holds at once, and what the window lets through between
// two looks.
int windowBatch(int threads) { return 4 * workerCount(threads); }

// Items [0, count) in batches of `batch` (at least one), the window between batches: fn(first,
// end) runs one batch (in parallel inside), then the window, told how far `part` of the work has
// come. The batches do not change any result.
template <class F>
void inBatches(int count, int batch, int threads, const LebWindow& window, WorkSpan part, F&& fn) {
  batch = std::max(1, batch);
  for (int first = 0; first < count; first += batch) {
    const int end = std::min(count, first + batch);
    fn(first, end);
    if (window) window(part.base + part.span * static_cast<double>(end) / static_cast<double>(count));
  }
}

// One channel in two passes over the runs, so that no more than one batch of runs' deltas and
// coded pages is ever held (section 3.1: one code for all pages): the counts for the code and the
// stored pages, then the deltas again, each page coded as soon as it is predicted and handed to
// `write` at `offset` onward, run by run in order. The descriptor goes before the pages: its place
// is kept and it is written after them. Returns the offset after the channel.
std::uint64_t encodeChannel(const HzOrder& order, const Dims3& dims, const ChannelSpec& spec, int pageBits,
                            LebCoder coder, const InsideValues& inside, int threads, const LebWindow& window,
                            WorkSpan part, const LebStreamWrite& write, std::uint64_t offset) {
  const bool lead1 = coder == LebCoder::Lead1;
  const ChannelPrediction prediction(order, dims, spec, pageBits, inside);
  const int runs = static_cast<int>(prediction.runs());
  std::vector<std::unique_ptr<Lead1Counter>> counters(static_cast<std::size_t>(runs));  // runs with a stored page
  std::vector<std::size_t> storedInRun(static_cast<std::size_t>(runs), 0);
  inBatches(runs, windowBatch(threads), threads, window, {part.base, part.span / 2}, [&](int first, int end) {
    parallelFor(end - first, threads, [&](int i) {
      const auto r = static_cast<std::size_t>(first + i);
      const RunDeltas d = prediction.run(r);
      storedInRun[r] = d.pages.size();
      if (lead1)  // the adaptive coder needs no counts
        for (const auto& page : d.pages) {
          if (!counters[r]) counters[r] = std::make_unique<Lead1Counter>(spec.valueBits);
          counters[r]->add(page);
        }
    });
  });
  Lead1Counter counter(spec.valueBits);
  for (const auto& c : counters)
    if (c) counter.merge(*c);
  counters.clear();
  LebChannelTable table{
      spec.kind, spec.components, spec.valueBits, spec.isSigned, lead1 ? counter.code() : Lead1Code{}, {}, {}, {},
      coder};
  std::size_t stored = 0;
  for (const std::size_t n : storedInRun) stored += n;
  const std::uint64_t descriptorAt = offset;
  offset += lebDescriptorSize(spec.valueBits, stored, coder);
  const std::optional<Lead1Encoder> encoder = lead1 ? std::optional<Lead1Encoder>(table.code) : std::nullopt;
  struct CodedRun {
    std::vector<std::uint32_t> storedPage, crc;
    std::vector<std::string> bytes;
  };
  std::vector<CodedRun> coded;
  inBatches(runs, windowBatch(threads), threads, window, {part.base + part.span / 2, part.span / 2},
            [&](int first, int end) {
              coded.assign(static_cast<std::size_t>(end - first), {});
              parallelFor(end - first, threads, [&](int i) {
                RunDeltas d = prediction.run(static_cast<std::uint64_t>(first + i));
                CodedRun& c = coded[static_cast<std::size_t>(i)];
                for (const auto& page : d.pages) {
                  if (encoder) {
                    BitWriter w;
                    encoder->encodePage(page, w);
                    c.bytes.push_back(w.finish());
                  } else {
                    c.bytes.push_back(encodeAdaptivePage(page, spec.valueBits, spec.components));
                  }
                  c.crc.push_back(crc32(c.bytes.back()));
                }
                c.storedPage = std::move(d.storedPage);
              });
              for (const CodedRun& c : coded)
                for (std::size_t j = 0; j < c.bytes.size(); ++j) {
                  write(offset, c.bytes[j]);
                  offset += c.bytes[j].size();
                  table.storedPage.push_back(c.storedPage[j]);
                  table.pageLength.push_back(static_cast<std::uint32_t>(c.bytes[j].size()));
                  table.pageCrc.push_back(c.crc[j]);
                }
            });
  if (table.storedPage.size() != stored) throw std::logic_error("LEB encode: the two passes stored different pages");
  write(descriptorAt, lebDescriptorBytes(lebPageCount(order.grid(), pageBits), table));
  return offset;
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

void checkSpan(const LebVolumeIn& v, const LebEncodeOptions& o) {
  if (v.sampleBits != 8 && v.sampleBits != 16)
    throw std::invalid_argument("sample bits must be 8 or 16, got " + std::to_string(v.sampleBits));
  if ((v.data8 == nullptr) == (v.data16 == nullptr))
    throw std::invalid_argument("the LEB encoder needs the samples at 8 bits or at 16, exactly one of them");
  if (v.data8 && v.sampleBits != 8) throw std::invalid_argument("8-bit storage holds 8-bit samples only");
  if (o.deriveGradients && !o.gradients)
    throw std::invalid_argument("deriving the gradients needs gradients: options.gradients is false");
  if (lebStoresGradients(o) && !v.gradients) throw std::invalid_argument("the gradients channel needs the gradients");
  checkPageBits(o.pageBits);
}

// One batch of runs in flight per worker count: their deltas (4 bytes a value) and their coded
// pages (under 4 bytes a value, lead1_coder.h; a flush byte and a std::string per page).
std::uint64_t inFlightBytes(std::uint64_t samples, int components, const LebEncodeOptions& o) {
  const auto batch = static_cast<std::uint64_t>(4 * workerCount(o.threads));
  const std::uint64_t points = std::min(samples, batch * kPagesPerRun * (std::uint64_t{1} << o.pageBits));
  return points * static_cast<std::uint64_t>(components) * 8 + batch * kPagesPerRun * 64;
}

}  // namespace

std::uint64_t encodeLebTo(const LebVolumeIn& v, const LebEncodeOptions& o, const LebStreamWrite& write) {
  checkSpan(v, o);
  const LebGrid grid = lebGridCovering(v.dims);
  const HzOrder order(grid);
  if (o.coder == LebCoder::Context) {  // the samples, then any gradients channel (context_codec.h)
    const std::vector<std::uint32_t> stored = contextStoredPages(order, v.dims, o.pageBits);
    const bool gradients = lebStoresGradients(o);
    // The work of a channel is in proportion to its components (1 and 3).
    const double total = gradients ? 4.0 : 1.0;
    std::uint64_t end = encodeContextChannel(order, v, LebChannelKind::Data, stored, o.pageBits, o.threads,
                                             lebProgressPart(o.window, 0.0, 1.0 / total), write, kLebHeaderBytes);
    if (gradients)
      end = encodeContextChannel(order, v, LebChannelKind::Gradients, stored, o.pageBits, o.threads,
                                 lebProgressPart(o.window, 1.0 / total, 3.0 / total), write, end);
    write(0,
          lebHeaderBytes(v.dims, v.sampleBits, grid, o.pageBits, gradients ? 2 : 1, end, o.coder, o.deriveGradients));
    return end;
  }
  std::vector<LebChannelKind> kinds{LebChannelKind::Data};
  if (lebStoresGradients(o)) kinds.push_back(LebChannelKind::Gradients);
  std::uint64_t offset = kLebHeaderBytes;
  // The work of a channel is in proportion to its components (1 and 3).
  const double total = lebStoresGradients(o) ? 4.0 : 1.0;
  double done = 0.0;
  for (LebChannelKind kind : kinds) {
    const ChannelSpec spec = specOf(kind, v.sampleBits);
    offset = encodeChannel(order, v.dims, spec, o.pageBits, o.coder, insideOf(v, kind), o.threads, o.window,
                           {done / total, spec.components / total}, write, offset);
    done += spec.components;
  }
  write(0, lebHeaderBytes(v.dims, v.sampleBits, grid, o.pageBits, static_cast<int>(kinds.size()), offset, o.coder,
                          o.deriveGradients));  // checkSpan: deriveGradients implies gradients
  return offset;
}

std::string encodeLeb(const LebVolumeIn& v, const LebEncodeOptions& o) {
  std::string stream;
  encodeLebTo(v, o, [&](std::uint64_t offset, std::string_view bytes) {
    if (offset + bytes.size() > stream.size()) stream.resize(offset + bytes.size());
    bytes.copy(stream.data() + offset, bytes.size());
  });
  return stream;
}

std::string encodeLeb(const Volume<std::uint16_t>& volume, int sampleBits, const LebEncodeOptions& o) {
  checkSamples(volume, sampleBits);
  const std::vector<std::int8_t> gradients =
      lebStoresGradients(o) ? quantizedGradients(volume) : std::vector<std::int8_t>{};
  return encodeLeb(LebVolumeIn{volume.dims(), sampleBits, nullptr, volume.data().data(),
                               gradients.empty() ? nullptr : gradients.data()},
                   o);
}

std::uint64_t lebEncodeToMemoryBytes(const Dims3& dims, const LebEncodeOptions& o) {
  checkPageBits(o.pageBits);
  const LebGrid grid = lebGridCovering(dims);
  const std::uint64_t samples = sampleCount(dims);
  const std::uint64_t pages = lebPageCount(grid, o.pageBits);
  const std::uint64_t stored = std::min(pages, samples);  // a stored page holds a point of the volume
  const std::uint64_t shell = LebPadding::tableBytes(grid, dims);
  // The runs' counters and stored-page counts; the page table (12 bytes a stored page and channel)
  // and the descriptor made from it.
  const std::uint64_t runs = runsOf(pages);
  const std::uint64_t tables = runs * 96 + std::min(runs, samples) * (17 * 17 * 8 + 64) + stored * 2 * 24;
  return shell + inFlightBytes(samples, lebStoresGradients(o) ? 3 : 1, o) + tables;
}

std::uint64_t lebEncodeMemoryBytes(const Dims3& dims, const LebEncodeOptions& o) {
  const std::uint64_t samples = sampleCount(dims);
  const std::uint64_t stored = std::min(lebPageCount(lebGridCovering(dims), o.pageBits), samples);
  // The stream: under 4 bytes a value, a flush byte per page, the descriptors; a growing string
  // holds up to three times that while it moves.
  const std::uint64_t stream = 4 * samples * (lebStoresGradients(o) ? 4 : 1) + stored * 2 * 16 + 4096;
  return lebEncodeToMemoryBytes(dims, o) + (lebStoresGradients(o) ? 3 * samples : 0) + 3 * stream;
}

std::uint64_t lebDecodeMemoryBytes(const LebStream& s) {
  const std::uint64_t samples = sampleCount(s.dims);
  return (s.hasGradients() ? 5 : 2) * samples + lebDecodeShellBytes(s);
}

std::uint64_t lebDecodeShellBytes(const LebStream& s) {
  // One a channel, held together (the data and gradients are decoded in one walk); none for the
  // context coder, whose predictions read corners inside the volume only.
  if (s.coder == LebCoder::Context) return 0;
  return LebPadding::tableBytes(s.grid, s.dims) * s.channels.size();
}

namespace {

// The whole-volume decoder's order of a level's pages: by tiles of kSlabSide^3 voxels, z slowest,
// then x within a row of tiles (coordinates below 2^21: k <= 11).
constexpr int kSlabSideLog2 = 5;
std::uint64_t slabKey(const GridPoint& p) {
  const auto c = [&](int a) { return static_cast<std::uint64_t>(p[a]); };
  return ((c(2) >> kSlabSideLog2) << 42) | ((c(1) >> kSlabSideLog2) << 21) | c(0);
}

// The gradients of a stream that derives them (FORMAT.md, header byte 23): those of the decoded
// samples, in batches of slices with the window between them (a slice reads its own samples and
// those of the slices beside it).
void deriveGradients(const LebVolumeOut& out, int threads, const LebWindow& window, WorkSpan part) {
  std::function<void(double)> afterBatch;
  if (window) afterBatch = [&](double done) { window(part.base + part.span * done); };
  withLebSamples(
      out, [&](const auto* samples) { quantizedGradientsInto(samples, out.dims, out.gradients, threads, afterBatch); });
}

// One channel of a whole-volume decode: the inputs of its predictions (the output itself, where
// the coarser levels are already written, and the shell of the padding) and its open pages.
struct ChannelDecode {
  const LebChannel& channel;
  ChannelSpec spec;
  InsideValues inside;
  LebPadding padding;
  std::map<std::uint64_t, std::optional<LebPageReader>> open;
  ChannelDecode(const LebStream& s, const LebChannel& c, const LebVolumeOut& out)
      : channel(c),
        spec(specOf(c)),
        inside(insideOf(LebVolumeIn{out.dims, out.sampleBits, out.data8, out.data16, out.gradients}, c.kind)),
        padding(s.grid, s.dims, spec.components) {}
  std::uint32_t mask() const { return static_cast<std::uint32_t>((std::uint64_t{1} << spec.valueBits) - 1); }
};

// Calls f(values, stores...) with what the walk of a segment of `group`'s channels reads
// (ChannelValues of the one channel, or SampleAndGradientValues of the two) and one ChannelStore
// per channel, over the segment's deltas d[j] of channel j.
template <class F>
void withSegment(const LebVolumeOut& out, const std::vector<ChannelDecode*>& group, const SegmentDeltas* d, F&& f) {
  if (group.size() == 1) {
    const ChannelDecode& c = *group[0];
    withChannel(out, c.spec.kind, [&](auto* target) {
      using T = std::remove_pointer_t<decltype(target)>;
      ChannelStore<T> store{target, c.mask(), d[0].deltas()};
      f(ChannelValues<T>{target, c.padding, c.inside}, store);
    });
    return;
  }
  const ChannelDecode &data = *group[0], &gradients = *group[1];
  auto withData = [&](auto* samples) {
    using D = std::remove_pointer_t<decltype(samples)>;
    ChannelStore<D> dataStore{samples, data.mask(), d[0].deltas()};
    ChannelStore<std::int8_t> gradientStore{out.gradients, gradients.mask(), d[1].deltas()};
    f(SampleAndGradientValues<D>{{samples, data.padding, data.inside},
                                 {out.gradients, gradients.padding, gradients.inside}},
      dataStore, gradientStore);
  };
  withLebSamples(out, withData);
}

// Decodes the channels of `group`: one channel, or a stream's data and gradients (channels 0 and
// 1, whose stored pages are the same) in one walk that predicts a point's sample and gradient
// together. `part` is the group's share of the work (the window's fractions).
//
// Level by level: the points of one level depend only on coarser ones, so the level's part of
// each stored page is reconstructed in parallel; a page's reader carries on where the previous
// level left it, and is finished (its end checked) once the walk has left the page. Between
// stored pages, the walk checks that no point of the volume lies in a page the stream lacks. A
// page is opened (its CRC checked) by the worker of its first segment, in parallel: a page has
// one segment a level, and the maps change only between the levels.
void decodeChannels(const LebStream& s, const HzOrder& order, const LebVolumeOut& out,
                    const std::vector<ChannelDecode*>& group, int threads, const LebWindow& window, WorkSpan part) {
  const int pb = s.pageBits;
  const LebChannel& first = group[0]->channel;
  const std::size_t channels = group.size();
  for (int level = -1; level < s.grid.levelCount(); ++level) {
    for (ChannelDecode* c : group) c->padding.addLevel(level, c->inside);
    const std::uint64_t begin = order.levelBegin(level), end = order.levelBegin(level + 1);
    if (begin == end) continue;
    // Segments of the level: a stored page's part of it, or a run of pages the stream lacks.
    struct Segment {
      std::uint64_t begin, end;
      bool stored;
      std::uint64_t page;
    };
    std::vector<Segment> segments;
    auto stored = std::lower_bound(first.storedPage.begin(), first.storedPage.end(), begin >> pb);
    for (std::uint64_t at = begin; at < end;) {
      if (stored != first.storedPage.end() && (std::uint64_t{*stored} << pb) < end) {
        const std::uint64_t page = *stored, pageBegin = std::max(begin, page << pb);
        if (at < pageBegin) segments.push_back({at, pageBegin, false, 0});
        at = std::min(end, (page + 1) << pb);
        segments.push_back({pageBegin, at, true, page});
        for (ChannelDecode* c : group) c->open[page];  // the map changes here only
        ++stored;
      } else {
        segments.push_back({at, end, false, 0});
        at = end;
      }
    }
    // The level's pages are independent of each other, so they are taken in slab order (tiles of
    // kSlabSide voxels in z, then y, then x, by the segment's first point) rather than in the
    // stream's hierarchical order, which comes back to an output row only after a whole octant:
    // under a resident window smaller than the outputs, that dropped rows still being written
    // and faulted them in again for every page (docs/leb.md, "Streaming between files"). The
    // bytes written are the same in any order.
    std::vector<std::array<std::uint64_t, 2>> keys(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const GridPoint p = order.point(segments[i].begin);
      keys[i] = {slabKey(p), i};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<Segment> sorted(segments.size());
    for (std::size_t i = 0; i < keys.size(); ++i) sorted[i] = segments[static_cast<std::size_t>(keys[i][1])];
    segments.swap(sorted);
    // In batches of kPagesPerRun segments per worker item, the window between batches. (Items of
    // 4 segments cut the 1024^3 bench's decode peak by 4 %, 1.73 to 1.66 GB, for 1.7 times the
    // time: batch overhead and refaults after trims.) Without a window the level is one batch:
    // its workers then start and meet once a level, not once a batch (the engine's decode on two
    // threads: 4.5 % of its time, docs/leb.md).
    const int perBatch = static_cast<int>(kPagesPerRun);
    // The group's indices up to this level's, and the level's share of them.
    const double grid = static_cast<double>(order.size());
    const WorkSpan levelPart{part.base + part.span * static_cast<double>(begin) / grid,
                             part.span * static_cast<double>(end - begin) / grid};
    const int items = (static_cast<int>(segments.size()) + perBatch - 1) / perBatch;
    inBatches(
        items, window ? windowBatch(threads) : items, threads, window, levelPart, [&](int firstItem, int lastItem) {
          const int from = firstItem * perBatch, to = std::min(static_cast<int>(segments.size()), lastItem * perBatch);
          // Two segments an item: their pages' deltas of each channel are decoded together
          // (readBoth). In chunks (parallelForChunked): the segments are in slab order, so a
          // worker's chunk is a block of the volume, about the same at every level, whose
          // parents it wrote itself (the engine's whole decode on 2 threads, median 218 to
          // 247 MB/s: docs/leb.md, "Kept").
          parallelForChunked((to - from + 1) / 2, threads, [&](int item) {
            const int at = from + 2 * item, itemEnd = std::min(to, at + 2);
            SegmentDeltas work[2][2];  // [segment][channel]
            int n = 0;
            for (int k = at; k < itemEnd; ++k) {
              const Segment& seg = segments[static_cast<std::size_t>(k)];
              if (!seg.stored) {  // pages the stream lacks: no point of the volume may lie in them
                const ChannelDecode& c = *group[0];
                walkInside(
                    order, s.dims, c.padding, c.inside, seg.begin, seg.end,
                    [&](std::uint64_t h, std::size_t, int, std::int32_t) { throw pageNotStored(c.channel, h >> pb); });
                continue;
              }
              // The segment's points inside the volume, one value a component each.
              const std::uint64_t points = order.countInside(s.dims, seg.begin, seg.end);
              for (std::size_t j = 0; j < channels; ++j) {
                ChannelDecode& c = *group[j];
                std::optional<LebPageReader>& reader = c.open.find(seg.page)->second;
                if (!reader) reader.emplace(openPage(s, c.channel, seg.page));
                work[n][j].allocate(*reader, seg.begin, seg.end,
                                    points * static_cast<std::uint64_t>(c.spec.components));
              }
              ++n;
            }
            for (std::size_t j = 0; j < channels; ++j) {
              if (n == 2)
                LebPageReader::readBoth(*work[0][j].reader, work[0][j].deltas(), *work[1][j].reader,
                                        work[1][j].deltas());
              else if (n == 1)
                work[0][j].reader->read(work[0][j].deltas());
            }
            for (int k = 0; k < n; ++k)
              withSegment(out, group, work[k], [&](const auto& values, auto&... stores) {
                reconstructSegment(order, s.dims, values, work[k][0].begin, work[k][0].end, stores...);
              });
          });
        });
    for (ChannelDecode* c : group)
      for (auto it = c->open.begin(); it != c->open.end() && std::min(order.size(), (it->first + 1) << pb) <= end;) {
        finishPage(*it->second, it->second->valuesRead() / static_cast<std::size_t>(c->spec.components), c->channel,
                   it->first);
        it = c->open.erase(it);
      }
  }
  for (const ChannelDecode* c : group)
    if (!c->open.empty()) throw std::logic_error("LEB decode: a page outlived the grid");
}

}  // namespace

void decodeLebInto(const LebStream& s, const LebVolumeOut& out, int threads, const LebWindow& window) {
  const bool hasGradients = s.hasGradients();
  // A stream that derives its gradients gives them when asked (out.gradients set), one that stores
  // them always (they are decoded with the pages).
  const bool derive = s.derivedGradients && out.gradients != nullptr;
  if (out.dims != s.dims || out.sampleBits != s.sampleBits || (out.data8 == nullptr) == (out.data16 == nullptr) ||
      (out.data8 && s.sampleBits != 8) || !(s.derivedGradients || (out.gradients != nullptr) == hasGradients))
    throw std::invalid_argument("decodeLebInto: the output does not match the stream's " + dimsText(s.dims) + " uint" +
                                std::to_string(s.sampleBits) + (hasGradients ? " with gradients" : ""));
  const HzOrder order(s.grid);
  if (s.coder == LebCoder::Context) {  // the data channel and any gradients channel; then any derived gradients
    const double share = derive ? 0.5 : 1.0;
    decodeContextChannels(s, order, out, threads, lebProgressPart(window, 0.0, share));
    if (derive) deriveGradients(out, threads, window, {share, 1.0 - share});
    return;
  }
  // The work in units of one component's reconstruction: the data's one, a gradients channel's
  // three, the derivation of the gradients one (it reads the samples once, and is cheaper than a
  // component's walk).
  const double workUnits = static_cast<double>(s.channels.size() > 1 ? 4 : 1) + (derive ? 1.0 : 0.0);
  std::deque<ChannelDecode> decoders;
  for (const LebChannel& ch : s.channels) decoders.emplace_back(s, ch, out);
  // A stream's data and gradients go in one walk when they store the same pages (as every encoder
  // writes them), else one channel after the other; the same bytes either way.
  std::vector<std::vector<ChannelDecode*>> groups;
  if (decoders.size() == 2 && s.channels[0].storedPage == s.channels[1].storedPage)
    groups.push_back({&decoders[0], &decoders[1]});
  else
    for (ChannelDecode& d : decoders) groups.push_back({&d});
  double done = 0.0;
  for (const auto& group : groups) {
    double components = 0.0;
    for (const ChannelDecode* c : group) components += c->spec.components;
    decodeChannels(s, order, out, group, threads, window, {done / workUnits, components / workUnits});
    done += components;
  }
  if (derive) deriveGradients(out, threads, window, {done / workUnits, 1.0 - done / workUnits});
}

LebDecoded decodeLeb(const LebStream& s, int threads) {
  LebDecoded out;
  out.data = Volume<std::uint16_t>(s.dims);
  if (s.hasGradients()) out.gradients.assign(3 * sampleCount(s.dims), 0);
  decodeLebInto(s,
                LebVolumeOut{s.dims, s.sampleBits, nullptr, out.data.data().data(),
                             out.gradients.empty() ? nullptr : out.gradients.data()},
                threads);
  return out;
}

std::vector<std::int32_t> lebDeltas(const Volume<std::uint16_t>& volume, int sampleBits, LebChannelKind kind) {
  checkSamples(volume, sampleBits);
  const HzOrder order(lebGridCovering(volume.dims()));
  std::vector<std::int8_t> gradients;
  if (kind == LebChannelKind::Gradients) gradients = quantizedGradients(volume);
  const LebVolumeIn v{volume.dims(), sampleBits, nullptr, volume.data().data(), gradients.data()};
  const ChannelPrediction prediction(order, volume.dims(), specOf(kind, sampleBits), kMaxLebPageBits,
                                     insideOf(v, kind));
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
