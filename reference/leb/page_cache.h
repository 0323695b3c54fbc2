// A least-recently-used cache of decoded pages under a byte budget (Gregorski et al. 2004,
// section 5: "the amount of main memory available for uncompressed data was limited").
//
// Keys are opaque 64-bit numbers; a page is a DecodedPage (decoded_page.h: deltas or a context
// page's values) and its cost is its values' bytes. When an insertion
// takes the total over the budget, the least recently used pages are dropped until it fits; a
// page larger than the whole budget is handed out but not kept (a budget of 0 caches nothing).
// Pages are shared: a caller may keep one after it was evicted. Not thread-safe.
#pragma once

#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <unordered_map>
#include <vector>

#include "reference/leb/decoded_page.h"

namespace voxref::ref {

class PageCache {
 public:
  using Page = std::shared_ptr<const DecodedPage>;
  struct Stats {
    std::uint64_t hits = 0, misses = 0, evictions = 0;
    std::size_t bytes = 0, peakBytes = 0, pages = 0;
  };

  explicit PageCache(std::size_t budgetBytes) : budget_(budgetBytes) {}
  // The page under `key`, calling decode() on a miss.
  Page get(std::uint64_t key, const std::function<DecodedPage()>& decode);
  // The page under `key` if it is cached (a hit, made the most recent), else null (nothing counted).
  Page find(std::uint64_t key);
  // find() without taking a share of the page: valid until the next get(), which may evict it.
  // The two most recent pages are found without the index (a reader alternates between a point's
  // data page and its gradient page).
  const DecodedPage* peek(std::uint64_t key);
  // Whether `key` is cached, with no effect on the order or the counts.
  bool contains(std::uint64_t key) const { return index_.count(key) != 0; }
  const Stats& stats() const { return stats_; }
  std::size_t budget() const { return budget_; }

 private:
  struct Entry {
    std::uint64_t key;
    Page page;
  };
  std::size_t budget_;
  std::list<Entry> lru_;  // most recent first
  std::unordered_map<std::uint64_t, std::list<Entry>::iterator> index_;
  Stats stats_;
};

}  // namespace voxref::ref
