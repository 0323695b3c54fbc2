#include "conformance/cli/memory_policy.h"

#include <malloc.h>

namespace voxref::cli {

void keepFreedMemoryForReuse() {
  constexpr int kOneGiB = 1 << 30;
  // mallopt(3): M_MMAP_THRESHOLD set by hand also stops glibc's dynamic threshold; a request it
  // refuses leaves the default policy, which is slower and never wrong.
  mallopt(M_MMAP_THRESHOLD, kOneGiB);
  mallopt(M_TRIM_THRESHOLD, kOneGiB);
}

}  // namespace voxref::cli
