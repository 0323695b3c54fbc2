// Work split over threads without changing any result: items are independent and each is
// computed by the same code whatever thread takes it, so outputs are identical for every thread
// count (docs/design.md: deterministic on every run and thread count).
#pragma once

#include <functional>

namespace voxref::ref {

// The number of workers for a request: `threads` if positive, else the hardware concurrency.
int workerCount(int threads);

// Calls fn(i) for i in [0, count) on up to workerCount(threads) threads (the calling thread is
// one of them) and returns when all are done. `done` (optional) is called after each item,
// serialised, with the number of items finished so far: 1, 2, ..., count, in order. Exceptions from fn are rethrown
// (the first one) after join; once one is caught, no worker starts another item. Workers take the next item from one
// shared counter.
void parallelFor(int count, int threads, const std::function<void(int)>& fn, const std::function<void(int)>& done = {});

// parallelFor with the items in contiguous chunks, one a worker: worker w takes the items of
// chunk w in order, then helps with the other chunks (from their next item). The same items and
// the same guarantees; for work whose item i touches memory near items i +- 1, called again and
// again over the same ranges (the LEB decoder's levels: a worker then mostly reads what it wrote
// itself the level before, from its own core's cache).
void parallelForChunked(int count, int threads, const std::function<void(int)>& fn,
                        const std::function<void(int)>& done = {});

}  // namespace voxref::ref
