// An allocator for large arrays that are filled anew, or grow, at every step of a loop (the
// incremental extraction's leaf lists and vertex store): a block of at least kHugePageMinBytes is
// mapped on its own with mmap(2), on a 2 MiB boundary, and marked MADV_HUGEPAGE (transparent huge
// pages, the kernel's "madvise" mode), so its first touch faults once per 2 MiB instead of once
// per 4 KiB page; smaller blocks come from operator new. Where the kernel gives no huge pages the
// mapping behaves as any anonymous one. A freed large block goes back to the kernel at once: for
// arrays that are freed and made again every step, the heap (which keeps them) is the better home.
// Throws std::bad_alloc when the mapping fails.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace voxref::ref {

inline constexpr std::size_t kHugePageMinBytes = std::size_t{4} << 20;

void* allocateHugePageBlock(std::size_t bytes);
void freeHugePageBlock(void* p, std::size_t bytes) noexcept;

template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePageMinBytes) return static_cast<T*>(::operator new(bytes));
    return static_cast<T*>(allocateHugePageBlock(bytes));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < kHugePageMinBytes) {
      ::operator delete(p);
    } else {
      freeHugePageBlock(p, bytes);
    }
  }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
};

template <class T>
using HugePageVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace voxref::ref
