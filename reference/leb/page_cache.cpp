#include "reference/leb/page_cache.h"

#include <algorithm>

namespace voxref::ref {

const DecodedPage* PageCache::peek(std::uint64_t key) {
  // The two most recent pages without the index, the others through it.
  const auto holds = [&](std::list<Entry>::iterator at) { return at != lru_.end() && at->key == key; };
  auto it = lru_.begin();
  if (!holds(it) && (lru_.empty() || !holds(++it))) {
    const auto found = index_.find(key);
    if (found == index_.end()) return nullptr;
    it = found->second;
  }
  ++stats_.hits;
  lru_.splice(lru_.begin(), lru_, it);  // no effect on the most recent page
  return it->page.get();
}

PageCache::Page PageCache::find(std::uint64_t key) { return peek(key) ? lru_.front().page : nullptr; }

PageCache::Page PageCache::get(std::uint64_t key, const std::function<DecodedPage()>& decode) {
  if (Page hit = find(key)) return hit;
  ++stats_.misses;
  Page page = std::make_shared<const DecodedPage>(decode());
  const std::size_t cost = page->byteSize();
  if (cost > budget_) return page;
  while (stats_.bytes + cost > budget_ && !lru_.empty()) {
    stats_.bytes -= lru_.back().page->byteSize();
    index_.erase(lru_.back().key);
    lru_.pop_back();
    ++stats_.evictions;
  }
  lru_.push_front({key, page});
  index_[key] = lru_.begin();
  stats_.bytes += cost;
  stats_.pages = lru_.size();
  stats_.peakBytes = std::max(stats_.peakBytes, stats_.bytes);
  return page;
}

}  // namespace voxref::ref
