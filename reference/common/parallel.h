// Work split over threads without changing any result: items are independent and each is
// computed by the same code whatever thread takes it, so outputs are identical for every thread
// count (docs/design.md: deterministic on every run and thread count).
#pragma once

#include <functional>

namespace voxref::ref {

// The number of workers for a request: `threads` if positive, else the hardware concurrency.
int workerCount(int threads);

// Calls fn(i) for i in [0, count) on up to workerCount(threads) threads (the calling thread is
// one of them) and returns when all are done. `done` (optional) is called, serialised, with the
// number of items finished so far. Exceptions from fn are rethrown (the first one) after join.
void parallelFor(int count, int threads, const std::function<void(int)>& fn, const std::function<void(int)>& done = {});

}  // namespace voxref::ref
