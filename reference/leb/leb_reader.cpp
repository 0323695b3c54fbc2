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

LebReader::Values LebReader::valueAt(const LebChannel& c, const GridPoint& p) {
  const LebGrid& grid = stream_->grid;
  if (!grid.contains(p)) order_.index(p);  // throws, naming the point
  // Keyed by the grid's linear index, which costs no walk of the hierarchy: the hierarchical
  // index is needed only for a point the memo lacks (to find its page).
  const std::uint64_t memoKey = (grid.linearIndex(p) << 1) | static_cast<std::uint64_t>(c.kind);
  if (const Values* known = memo_.find(memoKey)) return *known;
  Values pred{0, 0, 0};
  const LebPointClass pc = classifyPoint(stream_->grid, p);
  if (pc.level >= 0) {
    const SplitEdge e = splitEdgeOf(p, pc.scaleLog2, pc.oddAxes);
    const Values a = valueAt(c, e.a), b = valueAt(c, e.b);
    for (int k = 0; k < c.components; ++k)
      pred[static_cast<std::size_t>(k)] =
          predictMidpoint(a[static_cast<std::size_t>(k)], b[static_cast<std::size_t>(k)]);
  }
  Values v = pred;
  if (insideVolume(p, stream_->dims)) {
    const std::uint64_t h = order_.index(p);
    const std::uint64_t page = h >> stream_->pageBits;
    const std::uint64_t key = (page << 1) | static_cast<std::uint64_t>(c.kind);
    PageCache::Page deltas = cache_.find(key);  // the hit path builds no std::function
    if (!deltas) deltas = cache_.get(key, [&] { return decodePagePositions(*stream_, c, order_, page); });
    const std::size_t at =
        static_cast<std::size_t>(h - (page << stream_->pageBits)) * static_cast<std::size_t>(c.components);
    for (int k = 0; k < c.components; ++k)
      v[static_cast<std::size_t>(k)] = reconstructSample(
          pred[static_cast<std::size_t>(k)], (*deltas)[at + static_cast<std::size_t>(k)], c.valueBits, c.isSigned);
  }
  ++reconstructed_;
  memo_.try_emplace(memoKey, v);
  return v;
}

std::uint16_t LebReader::sample(const GridPoint& p) {
  beginQuery();
  return static_cast<std::uint16_t>(valueAt(channel(LebChannelKind::Data), p)[0]);
}

std::array<std::int8_t, 3> LebReader::gradient(const GridPoint& p) {
  beginQuery();
  const Values v = valueAt(channel(LebChannelKind::Gradients), p);
  return {static_cast<std::int8_t>(v[0]), static_cast<std::int8_t>(v[1]), static_cast<std::int8_t>(v[2])};
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
    const Values v = valueAt(c, cur.point());
    for (std::size_t k = 0; k < comps; ++k) out[static_cast<std::size_t>(cur.index() - begin) * comps + k] = v[k];
  }
  beginQuery();
  return out;
}

}  // namespace voxref::ref
