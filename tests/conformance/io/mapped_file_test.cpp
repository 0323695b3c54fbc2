#include "conformance/io/mapped_file.h"

#include <chrono>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "tests/scratch_folder.h"

namespace voxref::io {
namespace {

constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;

// Whether `done` holds within `limit`, asked every millisecond. statm's counts (fileResidentBytes)
// are per-CPU counters that the kernel sums lazily: on Linux 6.18 they trailed a 32 MiB touch by up
// to 30 MiB for a few milliseconds (50 runs of this file's window steps in a harness: 15 read the
// count under the window right after the touch, none 20 ms later), so tests of the window wait for
// them to come through.
constexpr std::chrono::milliseconds kCountsSettle{2000};
bool within(std::chrono::milliseconds limit, const std::function<bool()>& done) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

// Touches every page of `bytes` so that it is resident.
void touch(std::uint8_t* bytes, std::uint64_t size) {
  for (std::uint64_t i = 0; i < size; i += 4096) bytes[i] = static_cast<std::uint8_t>(i >> 12 | 1);
}

// The VmFlags of the mapping that holds `address`, from /proc/self/smaps (proc(5)); empty if none.
std::string vmFlagsOf(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  bool inside = false;
  for (std::string line; std::getline(smaps, line);) {
    std::uintptr_t begin = 0, end = 0;
    if (std::sscanf(line.c_str(), "%" SCNxPTR "-%" SCNxPTR " ", &begin, &end) == 2 && line.find('-') < 16) {
      inside = begin <= at && at < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line + " ";
    }
  }
  return "";
}

// adviseNoReadAround marks the mapping for random reads (VmFlags "rr": the kernel then reads no
// pages around a fault), and only it: a new mapping has no such flag.
TEST(MappedFile, AdviseNoReadAroundMarksTheMappingForRandomReads) {
  const test::ScratchFolder scratch;
  MappedFile file = MappedFile::create(scratch / "scratch.bin", 4 * kMiB);
  const std::string before = vmFlagsOf(file.data());
  ASSERT_NE(before, "") << "no mapping in /proc/self/smaps holds the file";
  EXPECT_EQ(before.find(" rr "), std::string::npos) << before;
  file.adviseNoReadAround();
  EXPECT_NE(vmFlagsOf(file.data()).find(" rr "), std::string::npos) << vmFlagsOf(file.data());
}

// The window counts the mappings' pages, not the heap: 64 MiB of freshly written heap must not
// make a 16 MiB window trim (the 2048x2048x1920 decode stalled when the codec's own heap passed the
// window by itself and every look trimmed), while 32 MiB of a watched mapping must.
TEST(ResidentWindow, TrimsForMappedPagesNotForTheHeap) {
  const test::ScratchFolder scratch;
  MappedFile file = MappedFile::create(scratch / "window.bin", 32 * kMiB);
  {
    const std::uint64_t before = fileResidentBytes();
    ResidentWindow window(16 * kMiB, {&file});
    const auto heap = std::make_unique<std::uint8_t[]>(64 * kMiB);
    touch(heap.get(), 64 * kMiB);
    window();
    EXPECT_EQ(window.trims(), 0);
    touch(file.data(), file.size());  // the watcher thread may trim while this runs
    EXPECT_TRUE(within(kCountsSettle, [&] {
      window();
      return window.trims() >= 1;
    }));
    // What is left is within the window.
    EXPECT_TRUE(within(kCountsSettle, [&] { return fileResidentBytes() <= before + 16 * kMiB; }))
        << fileResidentBytes() << " bytes resident";
  }
  // Nothing written was lost: the trimmed pages come back from the file.
  for (std::uint64_t i = 0; i < file.size(); i += 4096)
    ASSERT_EQ(file.data()[i], static_cast<std::uint8_t>(i >> 12 | 1));
}

}  // namespace
}  // namespace voxref::io
