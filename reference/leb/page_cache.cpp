#include "reference/leb/page_cache.h"

#include <algorithm>

namespace voxref::ref {

const std::vector<std::int16_t>* PageCache::peek(std::uint64_t key) {
  if (!lru_.empty()) {
    if (lru_.front().key == key) {  // already the most recent
      ++stats_.hits;
      return lru_.front().page.get();
    }
    if (const auto second = std::next(lru_.begin()); second != lru_.end() && second->key == key) {
      ++stats_.hits;
      lru_.splice(lru_.begin(), lru_, second);
      return second->page.get();
    }
  }
  const auto it = index_.find(key);
  if (it == index_.end()) return nullptr;
  ++stats_.hits;
  lru_.splice(lru_.begin(), lru_, it->second);
  return it->second->page.get();
}

PageCache::Page PageCache::find(std::uint64_t key) { return peek(key) ? lru_.front().page : nullptr; }

PageCache::Page PageCache::get(std::uint64_t key, const std::function<std::vector<std::int16_t>()>& decode) {
  if (Page hit = find(key)) return hit;
  ++stats_.misses;
  Page page = std::make_shared<const std::vector<std::int16_t>>(decode());
  const std::size_t cost = page->size() * sizeof(std::int16_t);
  if (cost > budget_) return page;
  while (stats_.bytes + cost > budget_ && !lru_.empty()) {
    stats_.bytes -= lru_.back().page->size() * sizeof(std::int16_t);
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
