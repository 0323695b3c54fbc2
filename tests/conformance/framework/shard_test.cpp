#include "conformance/framework/shard.h"

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>

namespace voxref::conf {
namespace {

std::vector<Case> numbered(int n) {
  std::vector<Case> cases;
  for (int i = 0; i < n; ++i) cases.push_back(Case{"case." + std::to_string(i), "test", "", {}, std::nullopt});
  return cases;
}

TEST(Shard, ShardsPartitionTheSelectionEvenly) {
  for (int n : {0, 1, 7, 222})
    for (int count : {1, 2, 3, 5, 300}) {
      const std::vector<Case> all = numbered(n);
      std::multiset<std::string> seen;
      std::size_t smallest = all.size(), largest = 0;
      for (int index = 1; index <= count; ++index) {
        const auto part = shardOf(all, {index, count});
        smallest = std::min(smallest, part.size());
        largest = std::max(largest, part.size());
        for (const Case& c : part) seen.insert(c.id);
        EXPECT_EQ(shardOf(all, {index, count}).size(), part.size()) << "deterministic";
      }
      EXPECT_EQ(seen.size(), all.size()) << n << " cases in " << count << " shards";
      for (const Case& c : all) EXPECT_EQ(seen.count(c.id), 1u) << c.id;
      EXPECT_LE(largest - std::min(smallest, largest), 1u);
    }
}

TEST(Shard, KeepsCatalogueOrder) {
  const auto part = shardOf(numbered(10), {2, 3});
  ASSERT_EQ(part.size(), 3u);
  EXPECT_EQ(part[0].id, "case.1");
  EXPECT_EQ(part[1].id, "case.4");
  EXPECT_EQ(part[2].id, "case.7");
}

TEST(Shard, ParsesAndRejects) {
  const Shard s = parseShard("3/8");
  EXPECT_EQ(s.index, 3);
  EXPECT_EQ(s.count, 8);
  for (const char* bad : {"", "3", "0/2", "3/2", "1/0", "a/b", "1/2/3", "-1/2", "1 /2"})
    EXPECT_THROW(parseShard(bad), std::invalid_argument) << bad;
}

TEST(Shard, FractionKeepsEveryNthCaseAndCombinesWithShards) {
  const std::vector<Case> all = numbered(10);
  const auto third = fractionOf(all, 3);
  ASSERT_EQ(third.size(), 4u);
  EXPECT_EQ(third[1].id, "case.3");
  EXPECT_EQ(third[3].id, "case.9");
  EXPECT_EQ(fractionOf(all, 1).size(), 10u);
  EXPECT_EQ(fractionOf(all, 11).size(), 1u);
  EXPECT_THROW(fractionOf(all, 0), std::invalid_argument);
  // The shards of a fraction partition the fraction.
  std::multiset<std::string> seen;
  for (int i = 1; i <= 2; ++i)
    for (const Case& c : shardOf(third, {i, 2})) seen.insert(c.id);
  EXPECT_EQ(seen, (std::multiset<std::string>{"case.0", "case.3", "case.6", "case.9"}));
}

TEST(Shard, GitLabsVariablesGiveTheShard) {
  EXPECT_EQ(shardFromCiVariables(nullptr, nullptr), std::nullopt);
  const auto s = shardFromCiVariables("2", "3");
  ASSERT_TRUE(s);
  EXPECT_EQ(s->index, 2);
  EXPECT_EQ(s->count, 3);
  auto message = [](const char* i, const char* n) {
    try {
      shardFromCiVariables(i, n);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(message("1", nullptr).rfind("CI_NODE_INDEX is set but CI_NODE_TOTAL is not", 0), 0u);
  EXPECT_EQ(message(nullptr, "3").rfind("CI_NODE_TOTAL is set but CI_NODE_INDEX is not", 0), 0u);
  EXPECT_EQ(message("0", "3"),
            "CI_NODE_INDEX='0' and CI_NODE_TOTAL='3': expected whole numbers with 1 <= CI_NODE_INDEX <= CI_NODE_TOTAL");
  EXPECT_NE(message("4", "3"), "");
  EXPECT_NE(message("x", "3"), "");
}

}  // namespace
}  // namespace voxref::conf
