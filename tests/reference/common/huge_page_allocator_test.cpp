#include "reference/common/huge_page_allocator.h"

#include <cstdint>
#include <numeric>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

TEST(HugePageAllocator, LargeBlocksStartOnAHugePageAndKeepTheirContentsAsTheyGrow) {
  // Large blocks are mapped on 2 MiB boundaries (the kernel can only back aligned 2 MiB ranges
  // with huge pages); small ones come from operator new. Growing through both keeps every value.
  HugePageVector<std::uint64_t> v;
  std::uint64_t next = 0;
  bool sawLarge = false;
  while (v.size() < 3 * kHugePageMinBytes / sizeof(std::uint64_t)) {
    v.push_back(next++ * 0x9E3779B97F4A7C15ULL);
    if (v.capacity() * sizeof(std::uint64_t) >= kHugePageMinBytes) {
      sawLarge = true;
      ASSERT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % (std::uintptr_t{2} << 20), 0u) << v.size();
    }
  }
  EXPECT_TRUE(sawLarge);
  for (std::uint64_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i], i * 0x9E3779B97F4A7C15ULL) << i;
  v.clear();
  v.shrink_to_fit();  // gives the mapping back
  EXPECT_EQ(v.capacity(), 0u);
}

}  // namespace
}  // namespace voxref::ref
