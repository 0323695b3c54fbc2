#include "conformance/io/atomic_file.h"

#include <fstream>
#include <sstream>

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace voxref::io {

AtomicOutput::AtomicOutput(std::filesystem::path destination) : destination_(std::move(destination)) {
  const std::string stem = destination_.stem().string();
  const std::string ext = destination_.extension().string();
  temporary_ = destination_.parent_path() / (stem + ".tmp" + std::to_string(::getpid()) + ext);
}

AtomicOutput::~AtomicOutput() {
  if (!committed_) {
    std::error_code ec;
    std::filesystem::remove(temporary_, ec);
  }
}

void AtomicOutput::commit() {
  std::error_code ec;
  std::filesystem::rename(temporary_, destination_, ec);
  if (ec) throw IoError("cannot move " + temporary_.string() + " to " + destination_.string() + ": " + ec.message());
  committed_ = true;
}

void writeFileAtomically(const std::filesystem::path& path, std::string_view content) {
  AtomicOutput out(path);
  std::FILE* f = std::fopen(out.temporary().c_str(), "wb");
  if (!f) throw IoError("cannot create " + out.temporary().string() + ": " + std::strerror(errno));
  const std::size_t written = std::fwrite(content.data(), 1, content.size(), f);
  const int flushed = std::fflush(f);
  const int err = errno;
  const int synced = flushed == 0 ? ::fsync(::fileno(f)) : -1;
  const int closed = std::fclose(f);
  if (written != content.size() || flushed != 0 || synced != 0 || closed != 0)
    throw IoError("cannot write " + path.string() + ": " + std::strerror(err ? err : EIO));
  out.commit();
}

void ensureDirectory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw IoError("cannot create directory " + dir.string() + (ec ? ": " + ec.message() : ""));
}

std::string readWholeFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw IoError(path.string() + " does not exist");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open " + path.string());
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw IoError("cannot read " + path.string());
  return std::move(ss).str();
}

}  // namespace voxref::io
