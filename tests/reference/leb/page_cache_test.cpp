#include "reference/leb/page_cache.h"

#include <vector>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

// A page of n int16 deltas costs 2n bytes.
std::function<DecodedPage()> page(std::size_t n, int* decodes) {
  return [n, decodes] {
    ++*decodes;
    DecodedPage deltas = DecodedPage::deltas(n, 16);
    for (std::size_t i = 0; i < n; ++i) deltas.set(i, 7);
    return deltas;
  };
}

TEST(PageCache, KeepsTheMostRecentlyUsedPagesWithinTheBudget) {
  PageCache cache(3 * 200);  // three pages of 100 values
  int decodes = 0;
  cache.get(1, page(100, &decodes));
  cache.get(2, page(100, &decodes));
  cache.get(3, page(100, &decodes));
  cache.get(1, page(100, &decodes));  // hit; 2 is now the least recently used
  cache.get(4, page(100, &decodes));  // evicts 2
  EXPECT_EQ(decodes, 4);
  cache.get(1, page(100, &decodes));
  cache.get(3, page(100, &decodes));
  EXPECT_EQ(decodes, 4);
  cache.get(2, page(100, &decodes));  // was evicted: decoded again
  EXPECT_EQ(decodes, 5);
  EXPECT_EQ(cache.stats().hits, 3u);
  EXPECT_EQ(cache.stats().misses, 5u);
  EXPECT_EQ(cache.stats().evictions, 2u);
  EXPECT_LE(cache.stats().bytes, 600u);
  EXPECT_EQ(cache.stats().peakBytes, 600u);
}

// contains() answers without counting and without changing which page is evicted next.
TEST(PageCache, ContainsChangesNothing) {
  PageCache cache(2 * 200);  // two pages of 100 values
  int decodes = 0;
  cache.get(1, page(100, &decodes));
  cache.get(2, page(100, &decodes));
  EXPECT_TRUE(cache.contains(1));
  EXPECT_FALSE(cache.contains(3));
  EXPECT_EQ(cache.stats().hits, 0u);
  EXPECT_EQ(cache.stats().misses, 2u);
  cache.get(3, page(100, &decodes));  // 1 is still the least recently used: evicted
  EXPECT_FALSE(cache.contains(1));
  EXPECT_TRUE(cache.contains(2));
  EXPECT_TRUE(cache.contains(3));
}

TEST(PageCache, FindIsAHitOrNothing) {
  PageCache cache(2 * 200);  // two pages of 100 values
  int decodes = 0;
  EXPECT_EQ(cache.find(1), nullptr);
  EXPECT_EQ(cache.stats().misses, 0u);
  cache.get(1, page(100, &decodes));
  cache.get(2, page(100, &decodes));
  ASSERT_NE(cache.find(1), nullptr);  // a hit: 2 is now the least recently used
  EXPECT_EQ(cache.stats().hits, 1u);
  cache.get(3, page(100, &decodes));  // evicts 2
  EXPECT_EQ(cache.find(2), nullptr);
  EXPECT_NE(cache.find(1), nullptr);
  EXPECT_EQ(decodes, 3);
  EXPECT_EQ(cache.stats().hits, 2u);
  EXPECT_EQ(cache.stats().misses, 3u);
}

TEST(PageCache, PeekMakesWhatItFindsTheMostRecentAsFindDoes) {
  // peek finds the most recent page and the second most recent without the index, and older ones
  // through it; each is a hit that leaves the page the most recent, as find's are.
  PageCache cache(2 * 200);  // two pages of 100 values
  int decodes = 0;
  cache.get(1, page(100, &decodes));
  cache.get(2, page(100, &decodes));  // recent first: 2 1
  EXPECT_EQ(cache.peek(9), nullptr);
  const DecodedPage* two = cache.peek(2);  // the most recent
  ASSERT_NE(two, nullptr);
  EXPECT_EQ(two, cache.find(2).get());
  ASSERT_NE(cache.peek(1), nullptr);  // the second: 1 2
  cache.get(3, page(100, &decodes));  // evicts 2: 3 1
  EXPECT_EQ(cache.find(2), nullptr);
  ASSERT_NE(cache.find(1), nullptr);  // 1 3
  cache.get(4, page(100, &decodes));  // evicts 3: 4 1
  cache.get(5, page(100, &decodes));  // evicts 1: 5 4
  ASSERT_NE(cache.peek(4), nullptr);  // the second: 4 5
  cache.get(6, page(100, &decodes));  // evicts 5
  EXPECT_EQ(cache.find(5), nullptr);
  EXPECT_NE(cache.find(4), nullptr);
  EXPECT_EQ(cache.stats().hits, 6u);  // peek 2, find 2, peek 1, find 1, peek 4, find 4
  EXPECT_EQ(cache.stats().misses, 6u);
  EXPECT_EQ(decodes, 6);
}

TEST(PageCache, APageLargerThanTheBudgetIsHandedOutButNotKept) {
  PageCache cache(100);
  int decodes = 0;
  const auto p = cache.get(9, page(1000, &decodes));
  EXPECT_EQ(p->size(), 1000u);
  cache.get(9, page(1000, &decodes));
  EXPECT_EQ(decodes, 2);
  EXPECT_EQ(cache.stats().bytes, 0u);
}

// A context page's values cost what they hold: a byte each at 8 bits (the gradients' read as int8),
// two at 16.
TEST(PageCache, ValuePagesCostTheirValuesBytes) {
  DecodedPage bytes = DecodedPage::values(100, 8);
  bytes.set(0, 200);
  bytes.set(1, -3);
  EXPECT_FALSE(bytes.holdsDeltas());
  EXPECT_EQ(bytes.value(0, false), 200);
  EXPECT_EQ(bytes.value(1, true), -3);
  EXPECT_EQ(bytes.value(2, true), 0);
  DecodedPage words = DecodedPage::values(100, 16);
  words.set(5, 65535);
  EXPECT_EQ(words.value(5, false), 65535);
  PageCache cache(300);
  cache.get(1, [&] { return bytes; });
  EXPECT_EQ(cache.stats().bytes, 100u);
  cache.get(2, [&] { return words; });
  EXPECT_EQ(cache.stats().bytes, 300u);
  EXPECT_EQ(cache.stats().evictions, 0u);
}

// An 8-bit channel's deltas cost a byte each and read back as they were given, the ends of the
// two's complement range included; a 16-bit channel's, two.
TEST(PageCache, DeltaPagesCostAByteADeltaAtEightBits) {
  const std::vector<std::int16_t> eight{-128, -1, 0, 1, 127}, sixteen{-32768, -129, 128, 32767};
  DecodedPage narrow = DecodedPage::deltas(eight.size(), 8), wide = DecodedPage::deltas(sixteen.size(), 16);
  for (std::size_t i = 0; i < eight.size(); ++i) narrow.set(i, eight[i]);
  for (std::size_t i = 0; i < sixteen.size(); ++i) wide.set(i, sixteen[i]);
  EXPECT_TRUE(narrow.holdsDeltas());
  EXPECT_TRUE(wide.holdsDeltas());
  EXPECT_EQ(narrow.byteSize(), 5u);
  EXPECT_EQ(wide.byteSize(), 8u);
  for (std::size_t i = 0; i < eight.size(); ++i) EXPECT_EQ(narrow.delta(i), eight[i]) << i;
  for (std::size_t i = 0; i < sixteen.size(); ++i) EXPECT_EQ(wide.delta(i), sixteen[i]) << i;
}

TEST(PageCache, EvictedPagesStayValidForTheirHolders) {
  PageCache cache(200);
  int decodes = 0;
  const auto held = cache.get(1, page(100, &decodes));
  cache.get(2, page(100, &decodes));  // evicts 1
  EXPECT_EQ(held->size(), 100u);
  EXPECT_EQ(held->delta(99), 7);
}

}  // namespace
}  // namespace voxref::ref
