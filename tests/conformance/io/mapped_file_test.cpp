#include "conformance/io/mapped_file.h"

#include <cstring>
#include <memory>

#include <gtest/gtest.h>

#include "tests/scratch_folder.h"

namespace voxref::io {
namespace {

constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;

// Touches every page of `bytes` so that it is resident.
void touch(std::uint8_t* bytes, std::uint64_t size) {
  for (std::uint64_t i = 0; i < size; i += 4096) bytes[i] = static_cast<std::uint8_t>(i >> 12 | 1);
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
    window();
    EXPECT_GE(window.trims(), 1);
    EXPECT_LE(fileResidentBytes(), before + 16 * kMiB);  // what is left is within the window
  }
  // Nothing written was lost: the trimmed pages come back from the file.
  for (std::uint64_t i = 0; i < file.size(); i += 4096)
    ASSERT_EQ(file.data()[i], static_cast<std::uint8_t>(i >> 12 | 1));
}

}  // namespace
}  // namespace voxref::io
