#include "reference/leb/leb_reader.h"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

#include "reference/leb/context_codec.h"
#include "reference/leb/context_gradient_coder.h"
#include "reference/leb/context_value_coder.h"
#include "reference/leb/gradients.h"
#include "reference/leb/leb_page.h"
#include "reference/leb/prediction.h"

namespace voxref::ref {

namespace {

// Bricks of 4^3 points: the memo's slot order (leb_reader.h).
constexpr int kBrickLog2 = 2;

}  // namespace

LebReader::LebReader(std::shared_ptr<const LebStream> stream, std::size_t cacheBudgetBytes)
    : stream_(std::move(stream)), order_(stream_->grid), cache_(cacheBudgetBytes) {
  constexpr std::uint64_t kMaxAxis = (std::uint64_t{1} << kMaxIndexedLebK) + 1;
  static_assert(kMaxAxis * kMaxAxis * kMaxAxis < ~std::uint32_t{0}, "a grid's linear index fits the memo's key");
  requireIndexedGrid(stream_->grid, "random access (LebReader)");
  const auto n = static_cast<std::uint64_t>(stream_->grid.pointsPerAxis());
  bricksPerAxis_ = (n + (1u << kBrickLog2) - 1) >> kBrickLog2;
  const std::uint64_t brickedPoints = bricksPerAxis_ * bricksPerAxis_ * bricksPerAxis_ << (3 * kBrickLog2);
  const std::uint64_t slots =
      std::min<std::uint64_t>(std::max<std::uint64_t>(kMinMemoSlots, std::bit_floor(cacheBudgetBytes / kMemoSlotBytes)),
                              std::bit_ceil(brickedPoints));
  memo_.resize(static_cast<std::size_t>(slots));
  memoMask_ = slots - 1;
}

void LebReader::beginQuery() {
  ++query_;
  if (!queryOwn_.empty()) queryOwn_.clear();
}

LebReader::MemoSlot& LebReader::memoSlot(const GridPoint& p) {
  constexpr unsigned kIn = (1u << kBrickLog2) - 1;
  const auto x = static_cast<std::uint64_t>(p[0]), y = static_cast<std::uint64_t>(p[1]),
             z = static_cast<std::uint64_t>(p[2]);
  const std::uint64_t brick =
      ((z >> kBrickLog2) * bricksPerAxis_ + (y >> kBrickLog2)) * bricksPerAxis_ + (x >> kBrickLog2);
  const std::uint64_t within = (((z & kIn) << kBrickLog2 | (y & kIn)) << kBrickLog2) | (x & kIn);
  return memo_[static_cast<std::size_t>(((brick << (3 * kBrickLog2)) | within) & memoMask_)];
}

const LebChannel& LebReader::channel(LebChannelKind kind) const {
  const LebChannel* c = stream_->channel(kind);
  if (!c)
    throw std::invalid_argument(std::string("the stream has no ") +
                                (kind == LebChannelKind::Data ? "data" : "gradients") + " channel" +
                                (stream_->derivedGradients ? " (it derives its gradients from the data)" : ""));
  return *c;
}

void LebReader::requireGradients() const {
  if (!stream_->hasGradients()) throw std::invalid_argument("the stream has no gradients (encoded without them)");
}

LebReader::Known LebReader::valueAt(unsigned want, const GridPoint& p) {
  const LebGrid& grid = stream_->grid;
  if (!grid.contains(p)) order_.index(p);  // throws, naming the point
  // Keyed by the grid's linear index, which costs no walk of the hierarchy: the hierarchical
  // index is needed only for a point the memo lacks (to find its page).
  const auto memoKey = static_cast<std::uint32_t>(grid.linearIndex(p));
  MemoSlot& slot = memoSlot(p);
  Known have;
  if (slot.key == memoKey) {
    have.v = {slot.data, slot.gradient[0], slot.gradient[1], slot.gradient[2]};
    have.channels = slot.channels;
  } else if (const Known* own = queryOwn_.empty() ? nullptr : queryOwn_.find(memoKey)) {
    have = *own;
  }
  if ((want & ~have.channels) == 0) return have;
  const unsigned need = want & ~have.channels;
  const bool inside = insideVolume(p, stream_->dims);
  // A stream that derives its gradients (FORMAT.md, header byte 23): a point inside the volume
  // takes its gradient from its neighbours' samples (below), so its split edge gives the rest; one
  // in the padding takes its prediction, as a padding point of a gradients channel does.
  const bool derive = stream_->derivedGradients && (need & 2u) != 0;
  // A context stream's pages hold the samples and the gradients themselves (FORMAT.md, "Context
  // pages", "Context gradient pages"): a point inside the volume needs no split edge for them.
  const unsigned fromEdge = inside ? need & ~(derive ? 2u : 0u) & ~(contextPages() ? 3u : 0u) : need;
  std::array<std::int32_t, 4> pred{0, 0, 0, 0};
  const LebPointClass pc = classifyPoint(grid, p);
  if (pc.level >= 0 && fromEdge != 0) {
    const SplitEdge e = splitEdgeOf(p, pc.scaleLog2, pc.oddAxes);
    const Known a = valueAt(fromEdge, e.a), b = valueAt(fromEdge, e.b);
    for (std::size_t i = 0; i < 4; ++i) pred[i] = predictMidpoint(a.v[i], b.v[i]);
  }
  const std::uint64_t h = inside ? order_.index(p, pc) : 0, page = h >> stream_->pageBits;
  for (const LebChannel& c : stream_->channels) {
    if (!(need & channelBit(c.kind))) continue;
    const std::size_t first = c.kind == LebChannelKind::Data ? 0 : 1, comps = static_cast<std::size_t>(c.components);
    for (std::size_t k = 0; k < comps; ++k) have.v[first + k] = pred[first + k];
    if (inside) {
      const std::uint64_t key = (page << 1) | static_cast<std::uint64_t>(c.kind);
      // The hit path builds no std::function and takes no share of the page.
      const DecodedPage* cached = cache_.peek(key);
      PageCache::Page decoded;  // a page larger than the budget lives only here
      if (!cached) {
        // A point that needs both channels, neither page cached: the two pages decode together,
        // their codes read interleaved (decodeChannelPagesPositions); this loop's next channel
        // then finds the gradients' page in the cache (or decodes it again, where the budget
        // cannot hold it).
        const std::uint64_t gradientsKey = (page << 1) | static_cast<std::uint64_t>(LebChannelKind::Gradients);
        if (c.kind == LebChannelKind::Data && (need & 2u) && !stream_->derivedGradients && !contextPages() &&
            !cache_.contains(gradientsKey)) {
          auto both = decodeChannelPagesPositions(*stream_, order_, page);
          cache_.get(gradientsKey, [&] { return std::move(both[1]); });
          decoded = cache_.get(key, [&] { return std::move(both[0]); });
        } else if (contextPages()) {
          decoded = cache_.get(key, [&] { return decodeContextPage(c, page); });
        } else {
          decoded = cache_.get(key, [&] { return decodePagePositions(*stream_, c, order_, page); });
        }
        cached = decoded.get();
      }
      const std::size_t at = static_cast<std::size_t>(h - (page << stream_->pageBits)) * comps;
      if (cached->holdsDeltas())
        for (std::size_t k = 0; k < comps; ++k)
          have.v[first + k] = reconstructSample(pred[first + k], cached->delta(at + k), c.valueBits, c.isSigned);
      else  // the values themselves: the samples, or the gradients' int8
        for (std::size_t k = 0; k < comps; ++k) have.v[first + k] = cached->value(at + k, c.isSigned);
    }
    ++reconstructed_;
  }
  if (derive) deriveGradient(p, inside, pred, have);
  have.channels |= need;
  // The slot, unless another point of this query holds it (the recursion may have filled it).
  if (slot.key == memoKey || slot.key == ~std::uint32_t{0} || slot.query != query_) {
    slot = {
        memoKey,
        query_,
        have.v[0],
        {static_cast<std::int8_t>(have.v[1]), static_cast<std::int8_t>(have.v[2]), static_cast<std::int8_t>(have.v[3])},
        static_cast<std::uint8_t>(have.channels)};
  } else if (auto [entry, inserted] = queryOwn_.try_emplace(memoKey, have); !inserted) {
    entry = have;
  }
  return have;
}

DecodedPage LebReader::decodeContextPage(const LebChannel& c, std::uint64_t page) {
  const StoredPage bytes = storedPage(*stream_, c, page);
  const std::uint64_t begin = page << stream_->pageBits;
  const auto comps = static_cast<std::size_t>(c.components);
  DecodedPage values = DecodedPage::values((std::size_t{1} << stream_->pageBits) * comps, c.valueBits);
  const auto get = [&](std::size_t i) { return values.value(i, c.isSigned); };
  const auto set = [&](std::size_t i, std::int32_t v) { values.set(i, v); };
  // A corner is coarser than its point: decoded before it in this page, or in an earlier page
  // (through the cache, recursively). Only a page that holds a coarser scale than its last point's
  // can hold corners of its points (contextPagesNeededBelow names the page itself then). The place
  // of a corner in this page, or none.
  const bool cornersInPage = contextPagesNeededBelow(order_, stream_->pageBits, page) == page;
  constexpr std::size_t kNone = ~std::size_t{0};
  const auto placeInPage = [&](const GridPoint& q) -> std::size_t {
    if (!cornersInPage) return kNone;
    const std::uint64_t hq = order_.index(q);
    return hq >= begin ? static_cast<std::size_t>(hq - begin) : kNone;
  };
  if (c.kind == LebChannelKind::Data) {
    ContextPageReader reader(bytes.bytes, c.valueBits, stream_->pageBits, page, bytes.offset, bytes.name);
    reader.decode(
        order_, stream_->dims,
        [&](const GridPoint& q) -> std::int32_t {
          if (const std::size_t at = placeInPage(q); at != kNone) return get(at);
          return valueAt(1u, q).v[0];
        },
        [&](std::uint64_t h, const GridPoint&, std::int32_t v) { set(static_cast<std::size_t>(h - begin), v); });
    return values;
  }
  ContextGradientPageReader reader(bytes.bytes, stream_->pageBits, page, bytes.offset, bytes.name);
  reader.decode(
      order_, stream_->dims,
      [&](const GridPoint& q) -> std::array<std::int8_t, 3> {
        if (const std::size_t at = placeInPage(q); at != kNone)
          return {static_cast<std::int8_t>(get(3 * at)), static_cast<std::int8_t>(get(3 * at + 1)),
                  static_cast<std::int8_t>(get(3 * at + 2))};
        const Known k = valueAt(2u, q);
        return {static_cast<std::int8_t>(k.v[1]), static_cast<std::int8_t>(k.v[2]), static_cast<std::int8_t>(k.v[3])};
      },
      [&](std::uint64_t h, const GridPoint&, const std::array<std::int8_t, 3>& g) {
        for (std::size_t k = 0; k < 3; ++k) set(static_cast<std::size_t>(h - begin) * 3 + k, g[k]);
      });
  return values;
}

void LebReader::deriveGradient(const GridPoint& p, bool inside, const std::array<std::int32_t, 4>& pred, Known& have) {
  if (!inside) {
    for (std::size_t k = 1; k < 4; ++k) have.v[k] = pred[k];
    return;
  }
  // gradients.h: the central differences of the samples, the same function the whole-volume
  // decoder and the encoder apply to an array; here each sample is reconstructed (and memoised).
  std::int8_t g[3];
  quantizeGradient(centralGradientAt(
                       [&](int x, int y, int z) {
                         return valueAt(1u, GridPoint{x, y, z}).v[0];
                       },
                       stream_->dims, p[0], p[1], p[2]),
                   g);
  for (std::size_t k = 0; k < 3; ++k) have.v[k + 1] = g[k];
}

std::uint16_t LebReader::sample(const GridPoint& p) {
  beginQuery();
  return static_cast<std::uint16_t>(valueAt(channelBit(channel(LebChannelKind::Data).kind), p).v[0]);
}

std::array<std::int8_t, 3> LebReader::gradient(const GridPoint& p) {
  beginQuery();
  requireGradients();
  const Known k = valueAt(channelBit(LebChannelKind::Gradients), p);
  return {static_cast<std::int8_t>(k.v[1]), static_cast<std::int8_t>(k.v[2]), static_cast<std::int8_t>(k.v[3])};
}

LebReader::SampleAndGradient LebReader::sampleAndGradient(const GridPoint& p) {
  (void)channel(LebChannelKind::Data);
  requireGradients();
  beginQuery();
  const Known k = valueAt(3u, p);
  return {static_cast<std::uint16_t>(k.v[0]),
          {static_cast<std::int8_t>(k.v[1]), static_cast<std::int8_t>(k.v[2]), static_cast<std::int8_t>(k.v[3])}};
}

std::vector<std::int32_t> LebReader::reconstructPage(LebChannelKind kind, std::uint64_t page) {
  const LebChannel& c = channel(kind);
  if (page >= stream_->pageCount())
    throw std::invalid_argument("page " + std::to_string(page) + " is outside the stream's " +
                                std::to_string(stream_->pageCount()) + " pages");
  beginQuery();
  const std::size_t comps = static_cast<std::size_t>(c.components);
  std::vector<std::int32_t> out((std::size_t{1} << stream_->pageBits) * comps, 0);
  const std::uint64_t begin = page << stream_->pageBits, end = std::min(order_.size(), (page + 1) << stream_->pageBits);
  for (HzCursor cur(order_, begin); cur.index() < end; cur.next()) {
    const Known v = valueAt(channelBit(kind), cur.point());
    const std::size_t slot = kind == LebChannelKind::Data ? 0 : 1;
    for (std::size_t k = 0; k < comps; ++k)
      out[static_cast<std::size_t>(cur.index() - begin) * comps + k] = v.v[slot + k];
  }
  beginQuery();
  return out;
}

}  // namespace voxref::ref
