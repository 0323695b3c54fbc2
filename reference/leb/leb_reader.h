// Random access into an LEB stream: any point or any page, decompressing only the pages needed
// (Gregorski et al. 2004, section 3.1, the four steps of reconstructing P(i,j,k)).
//
// value(p) finds p's page by its hierarchical index, takes the page's deltas from the cache
// (decoding the page on a miss), and adds them to the prediction from p's split edge, whose
// endpoint values are reconstructed the same way (recursively: the "reconstruction mask"; every
// endpoint is coarser, so the recursion ends at the root corners within 3k + 1 levels).
// Reconstructed values are memoised, per channel and grid point, and the memo is kept
// between queries while it holds at most cacheBudgetBytes / kMemoEntryBytes entries (it is
// emptied before a query when it holds more): neighbouring queries share their coarse ancestors,
// so a query in a region already visited reconstructs little more than its own point. A point is
// reconstructed at most once per query. Bit-identical to decodeLeb.
//
// Memory: the page cache's budget, plus the page being decoded (2^pageBits x components x 2 bytes,
// at most 6 MiB: pageBits <= 20 is checked by parseLebStream), plus the memo (about the budget
// again: kMemoEntryBytes covers an entry of its table; beyond that, the entries of one query:
// the points asked for and their coarser split-edge ancestors), plus reconstructPage's result,
// 2^pageBits x components x 4 bytes (at most 12 MiB).
// Nothing is allocated in proportion to the whole grid. Errors: StreamError for a corrupt
// page (when it is decoded), std::invalid_argument for a point outside the grid or a channel the
// stream lacks. Not thread-safe: use one reader per thread (they can share the stream).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "reference/common/flat_u64_map.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/leb_stream.h"
#include "reference/leb/page_cache.h"

namespace voxref::ref {

class LebReader {
 public:
  LebReader(std::shared_ptr<const LebStream> stream, std::size_t cacheBudgetBytes);

  const LebStream& stream() const { return *stream_; }
  // The data sample at p (a grid point; points of the padding give their predicted value).
  std::uint16_t sample(const GridPoint& p);
  // The quantized gradient at p.
  std::array<std::int8_t, 3> gradient(const GridPoint& p);
  // Every value of one page: 2^pageBits x components entries in hierarchical order (entries past
  // the grid's last point are 0).
  std::vector<std::int32_t> reconstructPage(LebChannelKind kind, std::uint64_t page);

  const PageCache::Stats& cacheStats() const { return cache_.stats(); }
  std::uint64_t pointsReconstructed() const { return reconstructed_; }

  // What the memo's capacity charges an entry, in bytes: the most its flat table (flat_u64_map.h)
  // spends on one, 4 slots of a key and three values.
  static constexpr std::size_t kMemoEntryBytes = 4 * (8 + 12);

 private:
  using Values = std::array<std::int32_t, 3>;
  // Starts a query: empties the memo if it is over its capacity.
  void beginQuery();
  Values valueAt(const LebChannel& c, const GridPoint& p);
  const LebChannel& channel(LebChannelKind kind) const;

  std::shared_ptr<const LebStream> stream_;
  HzOrder order_;
  PageCache cache_;
  std::size_t memoCapacity_;
  FlatU64Map<Values> memo_;  // (linear index, channel) -> values
  std::uint64_t reconstructed_ = 0;
};

}  // namespace voxref::ref
