#include "reference/common/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace voxref::ref {

int workerCount(int threads) {
  return threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

void parallelFor(int count, int threads, const std::function<void(int)>& fn, const std::function<void(int)>& done) {
  const int workers = std::max(1, std::min(workerCount(threads), count));
  std::atomic<int> next{0}, finished{0};
  std::mutex mutex;
  std::exception_ptr error;
  auto worker = [&] {
    for (int i = next++; i < count; i = next++) {
      try {
        fn(i);
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
        next = count;  // stop handing out work
        return;
      }
      const int n = ++finished;
      if (done) {
        std::lock_guard lock(mutex);
        done(n);
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace voxref::ref
