#include "reference/leb/leb_reader.h"

#include <stdexcept>
#include <string>

#include "reference/leb/leb_page.h"
#include "reference/leb/prediction.h"

namespace voxref::ref {

LebReader::LebReader(std::shared_ptr<const LebStream> stream, std::size_t cacheBudgetBytes)
    : stream_(std::move(stream)),
      order_(stream_->grid),
      cache_(cacheBudgetBytes),
      memoCapacity_(cacheBudgetBytes / kMemoEntryBytes) {}

void LebReader::beginQuery() {
  if (memo_.size() > memoCapacity_) memo_.clear();
}

const LebChannel& LebReader::channel(LebChannelKind kind) const {
  const LebChannel* c = stream_->channel(kind);
  if (!c)
    throw std::invalid_argument(std::string("the stream has no ") +
                                (kind == LebChannelKind::Data ? "data" : "gradients") + " channel");
  return *c;
}

LebReader::Known LebReader::valueAt(unsigned want, const GridPoint& p) {
  const LebGrid& grid = stream_->grid;
  if (!grid.contains(p)) order_.index(p);  // throws, naming the point
  // Keyed by the grid's linear index, which costs no walk of the hierarchy: the hierarchical
  // index is needed only for a point the memo lacks (to find its page).
  const std::uint64_t memoKey = grid.linearIndex(p);
  Known have;
  if (const Known* known = memo_.find(memoKey)) {
    if ((want & ~known->channels) == 0) return *known;
    have = *known;
  }
  const unsigned need = want & ~have.channels;
  std::array<std::int32_t, 4> pred{0, 0, 0, 0};
  const LebPointClass pc = classifyPoint(grid, p);
  if (pc.level >= 0) {
    const SplitEdge e = splitEdgeOf(p, pc.scaleLog2, pc.oddAxes);
    const Known a = valueAt(need, e.a), b = valueAt(need, e.b);
    for (std::size_t i = 0; i < 4; ++i) pred[i] = predictMidpoint(a.v[i], b.v[i]);
  }
  const bool inside = insideVolume(p, stream_->dims);
  const std::uint64_t h = inside ? order_.index(p) : 0, page = h >> stream_->pageBits;
  for (const LebChannel& c : stream_->channels) {
    if (!(need & channelBit(c.kind))) continue;
    const std::size_t slot = c.kind == LebChannelKind::Data ? 0 : 1, comps = static_cast<std::size_t>(c.components);
    for (std::size_t k = 0; k < comps; ++k) have.v[slot + k] = pred[slot + k];
    if (inside) {
      const std::uint64_t key = (page << 1) | static_cast<std::uint64_t>(c.kind);
      PageCache::Page deltas = cache_.find(key);  // the hit path builds no std::function
      if (!deltas) deltas = cache_.get(key, [&] { return decodePagePositions(*stream_, c, order_, page); });
      const std::size_t at = static_cast<std::size_t>(h - (page << stream_->pageBits)) * comps;
      for (std::size_t k = 0; k < comps; ++k)
        have.v[slot + k] = reconstructSample(pred[slot + k], (*deltas)[at + k], c.valueBits, c.isSigned);
    }
    ++reconstructed_;
  }
  have.channels |= need;
  if (auto [entry, inserted] = memo_.try_emplace(memoKey, have); !inserted) entry = have;
  return have;
}

std::uint16_t LebReader::sample(const GridPoint& p) {
  beginQuery();
  return static_cast<std::uint16_t>(valueAt(channelBit(channel(LebChannelKind::Data).kind), p).v[0]);
}

std::array<std::int8_t, 3> LebReader::gradient(const GridPoint& p) {
  beginQuery();
  const Known k = valueAt(channelBit(channel(LebChannelKind::Gradients).kind), p);
  return {static_cast<std::int8_t>(k.v[1]), static_cast<std::int8_t>(k.v[2]), static_cast<std::int8_t>(k.v[3])};
}

LebReader::SampleAndGradient LebReader::sampleAndGradient(const GridPoint& p) {
  (void)channel(LebChannelKind::Data);
  (void)channel(LebChannelKind::Gradients);
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
