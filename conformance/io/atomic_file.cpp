#include "conformance/io/atomic_file.h"

#include <atomic>
#include <fstream>
#include <memory>
#include <sstream>

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace voxref::io {

namespace {

// Follows a symbolic link to what it names, so that the link itself is never replaced.
std::filesystem::path resolved(const std::filesystem::path& p) {
  std::error_code ec;
  if (!std::filesystem::is_symlink(std::filesystem::symlink_status(p, ec))) return p;
  const std::filesystem::path target = std::filesystem::canonical(p, ec);
  return ec ? p : target;  // a dangling link: its place is written
}

std::string kindText(std::filesystem::file_type t) {
  switch (t) {
    case std::filesystem::file_type::directory:
      return "a directory";
    case std::filesystem::file_type::block:
      return "a block device";
    case std::filesystem::file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

// Writes `content` into the open file `f` and closes it; `sync` also flushes it to the disk.
// Errors name `path`, the destination.
void writeAndClose(std::FILE* f, const std::filesystem::path& path, std::string_view content, bool sync) {
  const std::size_t written = std::fwrite(content.data(), 1, content.size(), f);
  const int flushed = std::fflush(f);
  int err = errno;
  const int synced = sync && flushed == 0 ? ::fsync(::fileno(f)) : 0;
  if (synced != 0) err = errno;
  const int closed = std::fclose(f);
  if (written != content.size() || flushed != 0 || synced != 0 || closed != 0)
    throw IoError("cannot write " + path.string() + ": " + std::strerror(err ? err : EIO));
}

// Writes through a character device or FIFO (not atomic: outputKind()).
void writeStream(const std::filesystem::path& path, std::string_view content) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw IoError("cannot write " + path.string() + ": " + std::strerror(errno));
  writeAndClose(f, path, content, false);
}

// A name for a temporary that no other writer of this process uses.
std::string uniqueSuffix() {
  static std::atomic<unsigned> counter{0};
  return std::to_string(::getpid()) + "." + std::to_string(counter++);
}

}  // namespace

OutputKind outputKind(const std::filesystem::path& destination) {
  std::error_code ec;
  const std::filesystem::file_status st = std::filesystem::status(destination, ec);
  switch (st.type()) {
    case std::filesystem::file_type::not_found:
    case std::filesystem::file_type::regular:
      return OutputKind::Atomic;
    case std::filesystem::file_type::character:
    case std::filesystem::file_type::fifo:
      return OutputKind::Stream;
    case std::filesystem::file_type::none:
      if (ec && ec != std::errc::no_such_file_or_directory)
        throw IoError("cannot write " + destination.string() + ": " + ec.message());
      return OutputKind::Atomic;
    default:
      throw IoError("cannot write " + destination.string() + ": it is " + kindText(st.type()) +
                    " (voxref writes regular files, and writes through character devices and FIFOs)");
  }
}

namespace {

// The temporary of a destination of that kind (atomic_file.h, AtomicOutput).
std::filesystem::path temporaryFor(const std::filesystem::path& destination, OutputKind kind) {
  const std::string stem = destination.stem().string();
  const std::string ext = destination.extension().string();
  if (kind == OutputKind::Stream) {
    // Nothing is created beside a device or pipe (that folder may be /dev).
    std::error_code ec;
    const std::filesystem::path tmp = std::filesystem::temp_directory_path(ec);
    return (ec ? std::filesystem::path("/tmp") : tmp) / ("voxref-" + stem + ".tmp" + uniqueSuffix() + ext);
  }
  return destination.parent_path() / (stem + ".tmp" + std::to_string(::getpid()) + ext);
}

}  // namespace

AtomicOutput::AtomicOutput(std::filesystem::path destination)
    : destination_(resolved(destination)),
      kind_(outputKind(destination_)),
      temporary_(temporaryFor(destination_, kind_)),
      guard_(temporary_) {}

AtomicOutput::~AtomicOutput() {
  if (!committed_ || kind_ == OutputKind::Stream) {
    std::error_code ec;
    std::filesystem::remove(temporary_, ec);
  }
}

void AtomicOutput::commit() {
  if (kind_ == OutputKind::Stream) {
    writeStream(destination_, readWholeFile(temporary_));
    committed_ = true;
    return;
  }
  std::error_code ec;
  std::filesystem::rename(temporary_, destination_, ec);
  if (ec) throw IoError("cannot move " + temporary_.string() + " to " + destination_.string() + ": " + ec.message());
  committed_ = true;
}

namespace {

// Writes `content` to the temporary of `out`; errors name `path`, the destination.
void writeTemporary(const AtomicOutput& out, const std::filesystem::path& path, std::string_view content) {
  std::FILE* f = std::fopen(out.temporary().c_str(), "wb");
  if (!f)
    throw IoError("cannot write " + path.string() + ": cannot create " + out.temporary().string() + ": " +
                  std::strerror(errno));
  writeAndClose(f, path, content, true);
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& path, std::string_view content) {
  const std::filesystem::path target = resolved(path);
  if (outputKind(target) == OutputKind::Stream) return writeStream(target, content);
  AtomicOutput out(target);
  writeTemporary(out, path, content);
  out.commit();
}

void writeFilesAtomically(const std::vector<FileContent>& files) {
  // What would make a rename fail is refused before anything is written.
  std::vector<std::filesystem::path> targets;
  std::vector<OutputKind> kinds;
  for (std::size_t i = 0; i < files.size(); ++i) {
    targets.push_back(resolved(files[i].path));
    kinds.push_back(outputKind(targets[i]));  // throws for a directory, socket, block device
    for (std::size_t j = 0; j < i; ++j)
      if (targets[j].lexically_normal() == targets[i].lexically_normal())
        throw IoError("cannot write " + files[i].path.string() + " twice: two outputs name the same file");
  }
  // Regular files go to their temporaries first, then the streams are written through, then the
  // temporaries are renamed: a failure before the streams leaves nothing anywhere.
  std::vector<std::unique_ptr<AtomicOutput>> outs;
  for (std::size_t i = 0; i < files.size(); ++i)
    if (kinds[i] == OutputKind::Atomic) {
      outs.push_back(std::make_unique<AtomicOutput>(targets[i]));
      writeTemporary(*outs.back(), files[i].path, files[i].content);
    }
  for (std::size_t i = 0; i < files.size(); ++i)
    if (kinds[i] == OutputKind::Stream) writeStream(targets[i], files[i].content);
  for (auto& out : outs) out->commit();
}

void ensureDirectory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw IoError("cannot create directory " + dir.string() + (ec ? ": " + ec.message() : ""));
}

TemporaryFolder::TemporaryFolder(std::filesystem::path dir) : dir_(std::move(dir)) {
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);
  ensureDirectory(dir_);
}

TemporaryFolder::~TemporaryFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(dir_, ignored);
}

std::string readWholeFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw IoError(path.string() + (std::filesystem::exists(path, ec) ? " is not a regular file" : " does not exist"));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open " + path.string());
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw IoError("cannot read " + path.string());
  return std::move(ss).str();
}

}  // namespace voxref::io
