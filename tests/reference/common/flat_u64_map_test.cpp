#include "reference/common/flat_u64_map.h"

#include <array>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <unordered_map>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

// The oracle is std::unordered_map: the same sequence of insertions and lookups must give the same
// answers, through many doublings of the flat table and across clear().
TEST(FlatU64Map, AgreesWithStdUnorderedMapOverRandomInsertionsAndLookups) {
  std::mt19937_64 rng(7);
  FlatU64Map<std::array<std::int32_t, 3>> flat;
  std::unordered_map<std::uint64_t, std::array<std::int32_t, 3>> oracle;
  for (int round = 0; round < 3; ++round) {
    for (int i = 0; i < 200000; ++i) {
      // Keys that collide in their low bits (grid indices of neighbours) and some far apart.
      const std::uint64_t key = (i % 3 == 0) ? rng() >> 1 : (rng() % 50000) << (i % 7);
      const std::array<std::int32_t, 3> value{i, -i, round};
      const auto [v, inserted] = flat.try_emplace(key, value);
      const auto [it, oracleInserted] = oracle.try_emplace(key, value);
      ASSERT_EQ(inserted, oracleInserted) << "key " << key;
      ASSERT_EQ(v, it->second) << "key " << key;
      const std::uint64_t probe = rng() % 60000;
      const auto* found = flat.find(probe);
      const auto o = oracle.find(probe);
      ASSERT_EQ(found != nullptr, o != oracle.end()) << "probe " << probe;
      if (found != nullptr) {
        ASSERT_EQ(*found, o->second);
      }
    }
    ASSERT_EQ(flat.size(), oracle.size());
    flat.clear();
    oracle.clear();
    EXPECT_TRUE(flat.empty());
    EXPECT_EQ(flat.find(0), nullptr);
  }
}

// Erasing as well: keys drawn from a small range so that probe runs are long and wrap around the
// table's end, where backward-shift deletion has to decide cyclically which entries move.
TEST(FlatU64Map, AgreesWithStdUnorderedMapOverRandomInsertionsErasuresAndLookups) {
  std::mt19937_64 rng(11);
  FlatU64Map<std::uint32_t> flat;
  std::unordered_map<std::uint64_t, std::uint32_t> oracle;
  for (int i = 0; i < 400000; ++i) {
    const std::uint64_t key = (i % 5 == 0) ? rng() >> 1 : rng() % 3000;
    if (rng() % 3 == 0) {
      ASSERT_EQ(flat.erase(key), oracle.erase(key) == 1) << "key " << key;
    } else {
      const auto [v, inserted] = flat.try_emplace(key, static_cast<std::uint32_t>(i));
      const auto [it, oracleInserted] = oracle.try_emplace(key, static_cast<std::uint32_t>(i));
      ASSERT_EQ(inserted, oracleInserted) << "key " << key;
      ASSERT_EQ(v, it->second) << "key " << key;
    }
    ASSERT_EQ(flat.size(), oracle.size());
    const std::uint64_t probe = rng() % 3000;
    const std::uint32_t* found = flat.find(probe);
    const auto o = oracle.find(probe);
    ASSERT_EQ(found != nullptr, o != oracle.end()) << "probe " << probe;
    if (found != nullptr) {
      ASSERT_EQ(*found, o->second);
    }
  }
  for (const auto& [key, value] : oracle) {  // every survivor is still found from its home slot
    const std::uint32_t* found = flat.find(key);
    ASSERT_NE(found, nullptr) << "key " << key;
    ASSERT_EQ(*found, value);
  }
  EXPECT_FALSE(flat.erase(FlatU64Map<std::uint32_t>::kEmptyKey));
}

TEST(FlatU64Map, KeepsTheFirstValueOfAKeyAndRefusesTheReservedKey) {
  FlatU64Map<std::uint32_t> m;
  EXPECT_TRUE(m.try_emplace(0, 5).second);
  EXPECT_FALSE(m.try_emplace(0, 6).second);
  EXPECT_EQ(*m.find(0), 5u);
  EXPECT_THROW(m.try_emplace(FlatU64Map<std::uint32_t>::kEmptyKey, 1), std::invalid_argument);
  EXPECT_EQ(m.size(), 1u);
}

TEST(FlatU64Map, ResetEmptiesTheMapForItsNextFill) {
  // The refinement's queues rebuild their index every frame with reset: nothing of the last fill
  // may be found after it, whether the new fill is smaller or larger.
  FlatU64Map<std::uint32_t> m;
  for (std::uint64_t k = 0; k < 1000; ++k) m.try_emplace(k * 7919, static_cast<std::uint32_t>(k));
  for (const std::size_t n : {std::size_t{10}, std::size_t{5000}}) {
    m.reset(n);
    EXPECT_EQ(m.size(), 0u);
    for (std::uint64_t k = 0; k < 1000; ++k) ASSERT_EQ(m.find(k * 7919), nullptr) << k;
    for (std::uint64_t k = 0; k < n; ++k) ASSERT_TRUE(m.try_emplace(k * 31, static_cast<std::uint32_t>(k + 1)).second);
    EXPECT_EQ(m.size(), n);
    for (std::uint64_t k = 0; k < n; ++k) ASSERT_EQ(*m.find(k * 31), k + 1) << k;
  }
  EXPECT_THROW(m.reserve(4), std::logic_error);  // reserve stays for an empty map only
}

}  // namespace
}  // namespace voxref::ref
