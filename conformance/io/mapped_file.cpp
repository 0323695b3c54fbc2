#include "conformance/io/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>

#include "conformance/io/atomic_file.h"

namespace voxref::io {
namespace {

// Closes a descriptor when it goes out of scope (the mapping keeps the file).
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

MappedFile MappedFile::openRead(const std::filesystem::path& path) {
  std::error_code ec;
  const auto st = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(st)) throw IoError(path.string() + " does not exist");
  if (!std::filesystem::is_regular_file(st)) throw IoError(path.string() + " is not a regular file");
  Descriptor d{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (d.fd < 0) throw IoError("cannot open " + path.string() + ": " + std::strerror(errno));
  struct stat info {};
  if (::fstat(d.fd, &info) != 0) throw IoError("cannot open " + path.string() + ": " + std::strerror(errno));
  MappedFile m;
  m.path_ = path;
  m.size_ = static_cast<std::uint64_t>(info.st_size);
  if (m.size_ == 0) return m;
  void* p = ::mmap(nullptr, static_cast<std::size_t>(m.size_), PROT_READ, MAP_PRIVATE, d.fd, 0);
  if (p == MAP_FAILED) throw IoError("cannot map " + path.string() + ": " + std::strerror(errno));
  m.data_ = static_cast<std::uint8_t*>(p);
  return m;
}

MappedFile MappedFile::create(const std::filesystem::path& path, std::uint64_t size,
                              const std::filesystem::path& named) {
  const std::string name = (named.empty() ? path : named).string();
  Descriptor d{::open(path.c_str(), O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0644)};
  if (d.fd < 0) throw IoError("cannot write " + name + ": " + std::strerror(errno));
  MappedFile m;
  m.path_ = path;
  m.size_ = size;
  m.writable_ = true;
  if (size == 0) return m;
  if (const int err = ::posix_fallocate(d.fd, 0, static_cast<off_t>(size)); err != 0)
    throw IoError("cannot write " + name + ": " + std::strerror(err));
  void* p = ::mmap(nullptr, static_cast<std::size_t>(size), PROT_READ | PROT_WRITE, MAP_SHARED, d.fd, 0);
  if (p == MAP_FAILED)
    throw IoError("cannot write " + name + ": cannot map " + path.string() + ": " + std::strerror(errno));
  m.data_ = static_cast<std::uint8_t*>(p);
  return m;
}

MappedFile::MappedFile(MappedFile&& o) noexcept
    : path_(std::move(o.path_)), data_(o.data_), size_(o.size_), writable_(o.writable_) {
  o.data_ = nullptr;
  o.size_ = 0;
}

MappedFile& MappedFile::operator=(MappedFile&& o) noexcept {
  if (this != &o) {
    if (data_) ::munmap(data_, static_cast<std::size_t>(size_));
    path_ = std::move(o.path_);
    data_ = o.data_;
    size_ = o.size_;
    writable_ = o.writable_;
    o.data_ = nullptr;
    o.size_ = 0;
  }
  return *this;
}

MappedFile::~MappedFile() {
  if (data_) ::munmap(data_, static_cast<std::size_t>(size_));
}

void MappedFile::trim() {
  if (data_) ::madvise(data_, static_cast<std::size_t>(size_), MADV_DONTNEED);
}

void MappedFile::adviseNoReadAround() {
  if (data_) ::madvise(data_, static_cast<std::size_t>(size_), MADV_RANDOM);  // advice: no result changes
}

void MappedFile::flush() {
  if (data_ && writable_ && ::msync(data_, static_cast<std::size_t>(size_), MS_SYNC) != 0)
    throw IoError("cannot write " + path_.string() + ": " + std::strerror(errno));
}

std::uint64_t fileResidentBytes() {
  // statm's fields, in pages: size, resident, shared (resident file-backed and shmem pages); proc(5).
  std::ifstream statm("/proc/self/statm");
  std::uint64_t size = 0, resident = 0, shared = 0;
  statm >> size >> resident >> shared;
  static const auto pageBytes = static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));  // asked once
  return shared * pageBytes;
}

ResidentWindow::ResidentWindow(std::uint64_t budget, std::vector<MappedFile*> mappings)
    : budget_(budget), base_(fileResidentBytes()), mappings_(std::move(mappings)) {
  watcher_ = std::jthread([this](std::stop_token stop) {
    while (!stop.stop_requested()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(kResidentWindowPollMs));
      (*this)();
    }
  });
}

ResidentWindow::~ResidentWindow() {
  watcher_.request_stop();
  if (watcher_.joinable()) watcher_.join();
}

void ResidentWindow::operator()() {
  const std::uint64_t now = fileResidentBytes();
  if (now <= base_ || now - base_ <= budget_) return;
  const std::lock_guard<std::mutex> lock(mutex_);
  for (MappedFile* m : mappings_) m->trim();
  ++trims_;
}

}  // namespace voxref::io
