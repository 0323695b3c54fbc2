// Files mapped into memory, for codecs that stream volumes larger than the memory they may use
// (leb_file_codec.h): a mapping's resident pages can be dropped at any time (trim), so the
// process holds only what it touched since, while the kernel keeps the file in its page cache.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string_view>
#include <thread>
#include <vector>

namespace voxref::io {

class MappedFile {
 public:
  // The whole of a regular file, read-only. Throws IoError "<path> does not exist", "<path> is not
  // a regular file" or "cannot open <path>: <reason>". An empty file maps to no bytes.
  static MappedFile openRead(const std::filesystem::path& path);
  // A new file of `size` bytes, read-write and shared (what is written reaches the file). Its
  // blocks are allocated first (posix_fallocate), so a full disk or a file-size limit is an
  // IoError "cannot write <named>: <reason>" here, never a fault while writing through the mapping;
  // `named` is what the file is for (the destination of a temporary), `path` by default.
  static MappedFile create(const std::filesystem::path& path, std::uint64_t size,
                           const std::filesystem::path& named = {});

  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  ~MappedFile();

  const std::uint8_t* data() const { return data_; }
  std::uint8_t* data() { return data_; }
  std::uint64_t size() const { return size_; }
  const std::filesystem::path& path() const { return path_; }
  std::string_view bytes() const { return {reinterpret_cast<const char*>(data_), static_cast<std::size_t>(size_)}; }

  // Drops the mapping's resident pages (madvise MADV_DONTNEED). Nothing is lost: a read-only
  // mapping reads the file again, a shared one has handed its writes to the page cache.
  void trim();
  // Writes a shared mapping's pages to the file (msync); throws IoError naming it.
  void flush();
  // Turns off the kernel's read-around for this mapping (madvise MADV_RANDOM): a fault brings in
  // the page it needs and no more. For a scratch file written through its mapping and read back
  // under a ResidentWindow: with read-around, the 1025^3 buckyball's encode peaked at 1.75-2.52 GB
  // against a 512 MB window, without it at 0.70-0.78 GB (docs/leb.md, "Streaming between files").
  void adviseNoReadAround();

 private:
  MappedFile() = default;
  std::filesystem::path path_;
  std::uint8_t* data_ = nullptr;
  std::uint64_t size_ = 0;
  bool writable_ = false;
};

// The part of this process's resident memory that file mappings hold (/proc/self/statm's third
// field: file-backed and shared pages), in bytes: the pages a ResidentWindow can drop. The heap is
// not in it.
std::uint64_t fileResidentBytes();

// The working window of a streaming codec: whenever the file-backed pages this process gained
// since the window opened exceed `budget` bytes, it trims every mapping it watches. It counts file
// pages only (fileResidentBytes), because they are all a trim can drop: when it compared the whole
// process's resident memory, the codec's own heap (the shell of padding, the page readers) could
// pass the budget by itself, and from then on it trimmed every mapping at every look however little
// of them was resident (the 2048x2048x1920 decode stalled at 8 % that way, with 556 MB of heap and
// 92 MB of mapped pages). The heap is bounded by the codec's own memory bounds instead
// (lebFileEncodeAddressBytes, lebFileDecodeAddressBytes). A watcher thread looks every
// kResidentWindowPollMs while the window lives, because one batch of work can touch far more than
// the budget (the coarse levels of an LEB hierarchy reach every page of a 1025^3 volume and its
// gradients within one batch: the 1025^3 buckyball encode peaked at 3.29 GB before this thread, 2.12 GB polling every 5
// ms, 1.95 GB every 1 ms, against a 512 MB window); calling it between batches looks once more. Trimming drops pages
// from this process's page tables only (MADV_DONTNEED on shared file mappings: written pages stay in the file's page
// cache), so it changes no result, whichever thread is reading or writing the mapping. statm's counts are per-CPU
// counters that the kernel sums lazily, so the window sees pages late by their lag (up to 30 MiB for a few
// milliseconds on Linux 6.18, 2 CPUs: tests/conformance/io/mapped_file_test.cpp). The mappings must outlive the
// window.
inline constexpr int kResidentWindowPollMs = 1;
class ResidentWindow {
 public:
  ResidentWindow(std::uint64_t budget, std::vector<MappedFile*> mappings);
  ~ResidentWindow();
  ResidentWindow(const ResidentWindow&) = delete;
  ResidentWindow& operator=(const ResidentWindow&) = delete;
  void operator()();
  int trims() const { return trims_.load(); }

 private:
  std::uint64_t budget_;
  std::uint64_t base_;  // fileResidentBytes() when the window opened: the executable, its libraries
  std::vector<MappedFile*> mappings_;
  std::atomic<int> trims_{0};
  std::mutex mutex_;  // one trim at a time
  std::jthread watcher_;
};

}  // namespace voxref::io
