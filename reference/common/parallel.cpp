#include "reference/common/parallel.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace voxref::ref {
namespace {

// Items [0, count) in `chunks` contiguous ranges, each with its own next item; worker w starts in
// range w % chunks and, when that is used up, takes from the following ranges in turn. One range
// is one shared counter (parallelFor); one a worker is parallelForChunked.
void runItems(int count, int threads, bool chunked, const std::function<void(int)>& fn,
              const std::function<void(int)>& done) {
  const int workers = std::max(1, std::min(workerCount(threads), count));
  const int chunks = chunked ? workers : 1;
  auto chunkBegin = [&](int c) { return static_cast<int>(std::int64_t{count} * c / chunks); };
  std::vector<std::atomic<int>> next(static_cast<std::size_t>(chunks));
  for (int c = 0; c < chunks; ++c) next[static_cast<std::size_t>(c)] = chunkBegin(c);
  int finished = 0;  // items done, counted only for `done`
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::exception_ptr error;
  auto worker = [&](int w) {
    for (int k = 0; k < chunks; ++k) {
      const int c = (w + k) % chunks, end = chunkBegin(c + 1);
      std::atomic<int>& at = next[static_cast<std::size_t>(c)];
      for (int i = at++; i < end && !stop; i = at++) {
        try {
          fn(i);
        } catch (...) {
          std::lock_guard lock(mutex);
          if (!error) error = std::current_exception();
          stop = true;  // stop handing out work
          return;
        }
        if (done) {  // counted under the lock, so that done sees 1, 2, ... in order
          std::lock_guard lock(mutex);
          done(++finished);
        }
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(worker, t);
  worker(0);
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace

int workerCount(int threads) {
  return threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void parallelFor(int count, int threads, const std::function<void(int)>& fn, const std::function<void(int)>& done) {
  runItems(count, threads, false, fn, done);
}

void parallelForChunked(int count, int threads, const std::function<void(int)>& fn,
                        const std::function<void(int)>& done) {
  runItems(count, threads, true, fn, done);
}

}  // namespace voxref::ref
