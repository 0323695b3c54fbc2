// The move-to-front list of a gradient page's vectors (reference/leb/recent_vectors.h), against a
// plain list moved to the front by hand after every use.
#include "reference/leb/recent_vectors.h"

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

TEST(RecentVectors, RanksAndLookupsAreThoseOfAListMovedToTheFront) {
  for (const std::uint32_t alphabet : {1u, 3u, 40u, 5000u}) {
    const std::size_t uses = 3000;
    RecentVectors recent(uses);
    std::vector<std::uint32_t> list;  // most recent first
    std::mt19937 rng(alphabet);
    for (std::size_t u = 0; u < uses; ++u) {
      // Skewed: recent keys come back often, as gradients do.
      const std::uint32_t key = (rng() % 3 == 0 || list.empty())
                                    ? static_cast<std::uint32_t>(rng() % alphabet) * 7919u
                                    : list[std::min<std::size_t>(rng() % 4, list.size() - 1)];
      const auto it = std::find(list.begin(), list.end(), key);
      const std::optional<std::uint32_t> rank = recent.rankOf(key);
      if (it == list.end()) {
        ASSERT_FALSE(rank.has_value()) << "use " << u;
      } else {
        ASSERT_TRUE(rank.has_value()) << "use " << u;
        ASSERT_EQ(*rank, static_cast<std::uint32_t>(it - list.begin())) << "use " << u;
        list.erase(it);
      }
      list.insert(list.begin(), key);
      recent.use(key);
      ASSERT_EQ(recent.size(), list.size());
      if (u % 97 == 0) {
        for (std::uint32_t r = 0; r < list.size(); ++r)
          ASSERT_EQ(recent.at(r), list[r]) << "use " << u << " rank " << r;
      }
    }
  }
}

TEST(RecentVectors, MoreUsesThanItsCapacityAreRefused) {
  RecentVectors recent(2);
  recent.use(5);
  recent.use(5);
  EXPECT_THROW(recent.use(6), std::logic_error);
}

}  // namespace
}  // namespace voxref::ref
