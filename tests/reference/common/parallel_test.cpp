#include "reference/common/parallel.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <ostream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace voxref::ref {
namespace {

using Runner = void (*)(int, int, const std::function<void(int)>&, const std::function<void(int)>&);

struct Schedule {
  const char* name;
  Runner run;
};

void PrintTo(const Schedule& s, std::ostream* os) { *os << s.name; }

class ParallelFor : public ::testing::TestWithParam<Schedule> {};

TEST_P(ParallelFor, CallsEveryItemExactlyOnceAndCountsThemDone) {
  for (const int count : {0, 1, 2, 5, 1000})
    for (const int threads : {1, 2, 3, 8}) {
      std::vector<std::atomic<int>> calls(static_cast<std::size_t>(count));
      std::vector<int> doneCounts;
      GetParam().run(
          count, threads, [&](int i) { ++calls[static_cast<std::size_t>(i)]; },
          [&](int n) { doneCounts.push_back(n); });  // serialised by the contract
      for (int i = 0; i < count; ++i)
        ASSERT_EQ(calls[static_cast<std::size_t>(i)], 1)
            << "item " << i << " of " << count << ", " << threads << " threads";
      // done(n) for n = 1 .. count, once each, in the order the items finished.
      ASSERT_EQ(doneCounts.size(), static_cast<std::size_t>(count));
      for (std::size_t k = 0; k < doneCounts.size(); ++k) EXPECT_EQ(doneCounts[k], static_cast<int>(k) + 1);
    }
}

TEST_P(ParallelFor, OneThreadTakesTheItemsInOrderOnTheCallingThread) {
  std::vector<int> order;
  const std::thread::id caller = std::this_thread::get_id();
  GetParam().run(7, 1,
                 [&](int i) {
                   EXPECT_EQ(std::this_thread::get_id(), caller);
                   order.push_back(i);
                 },
                 {});
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
}

TEST_P(ParallelFor, RethrowsTheErrorOfAnItem) {
  for (const int threads : {1, 2, 4}) {
    std::vector<int> after;  // one thread: the items started after the error
    EXPECT_THROW(GetParam().run(200, threads,
                                [&](int i) {
                                  if (i == 3) throw std::runtime_error("item 3");
                                  if (threads == 1 && i > 3) after.push_back(i);
                                },
                                {}),
                 std::runtime_error)
        << threads << " threads";
    EXPECT_TRUE(after.empty()) << "one thread went on after the error, to item " << after.front();
  }
}

INSTANTIATE_TEST_SUITE_P(Schedules, ParallelFor,
                         ::testing::Values(Schedule{"shared", parallelFor}, Schedule{"chunked", parallelForChunked}),
                         [](const ::testing::TestParamInfo<Schedule>& p) { return std::string(p.param.name); });

TEST(ParallelForChunked, EachWorkerStartsWithItsOwnChunk) {
  // Two threads, four items: the calling thread starts at item 0, the other at item 2 (the second
  // chunk). Items 0 and 2 wait for each other, so neither worker can finish its first item and take
  // the other's chunk before both have started.
  std::mutex m;
  std::vector<std::pair<std::thread::id, int>> firsts;
  std::atomic<int> arrived{0};
  parallelForChunked(4, 2, [&](int i) {
    {
      std::lock_guard lock(m);
      bool seen = false;
      for (const auto& f : firsts) seen = seen || f.first == std::this_thread::get_id();
      if (!seen) firsts.emplace_back(std::this_thread::get_id(), i);
    }
    if (i == 0 || i == 2) {
      ++arrived;
      for (int spin = 0; arrived < 2 && spin < 10000; ++spin) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  ASSERT_EQ(firsts.size(), 2u);
  std::vector<int> firstItems{firsts[0].second, firsts[1].second};
  std::sort(firstItems.begin(), firstItems.end());
  EXPECT_EQ(firstItems, (std::vector<int>{0, 2}));
}

}  // namespace
}  // namespace voxref::ref
