#include "reference/common/huge_page_allocator.h"

#include <sys/mman.h>

#include <cstdint>

namespace voxref::ref {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
std::size_t mappedBytes(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }
}  // namespace

void* allocateHugePageBlock(std::size_t bytes) {
  // Huge pages need 2 MiB-aligned addresses: map one huge page more and unmap the slack.
  const std::size_t size = mappedBytes(bytes);
  void* p = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
  auto* raw = static_cast<char*>(p);
  const auto address = reinterpret_cast<std::uintptr_t>(raw);
  char* aligned = raw + (kHugePage - address % kHugePage) % kHugePage;
  if (aligned > raw) munmap(raw, static_cast<std::size_t>(aligned - raw));
  if (aligned + size < raw + size + kHugePage)
    munmap(aligned + size, static_cast<std::size_t>(raw + size + kHugePage - (aligned + size)));
  madvise(aligned, size, MADV_HUGEPAGE);  // advice only: without huge pages, 4 KiB faults
  return aligned;
}

void freeHugePageBlock(void* p, std::size_t bytes) noexcept { munmap(p, mappedBytes(bytes)); }

}  // namespace voxref::ref
