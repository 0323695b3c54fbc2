#include "conformance/io/atomic_file.h"

#include <fstream>
#include <memory>
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

namespace {

// Writes `content` to the temporary of `out`; errors name `path`, the destination.
void writeTemporary(const AtomicOutput& out, const std::filesystem::path& path, std::string_view content) {
  std::FILE* f = std::fopen(out.temporary().c_str(), "wb");
  if (!f) throw IoError("cannot write " + path.string() + ": cannot create " + out.temporary().string() + ": " + std::strerror(errno));
  const std::size_t written = std::fwrite(content.data(), 1, content.size(), f);
  const int flushed = std::fflush(f);
  const int err = errno;
  const int synced = flushed == 0 ? ::fsync(::fileno(f)) : -1;
  const int closed = std::fclose(f);
  if (written != content.size() || flushed != 0 || synced != 0 || closed != 0)
    throw IoError("cannot write " + path.string() + ": " + std::strerror(err ? err : EIO));
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& path, std::string_view content) {
  AtomicOutput out(path);
  writeTemporary(out, path, content);
  out.commit();
}

void writeFilesAtomically(const std::vector<FileContent>& files) {
  // What would make a rename fail is refused before anything is written.
  for (std::size_t i = 0; i < files.size(); ++i) {
    std::error_code ec;
    if (std::filesystem::is_directory(files[i].path, ec)) throw IoError("cannot write " + files[i].path.string() + ": it is a directory");
    for (std::size_t j = 0; j < i; ++j)
      if (files[j].path.lexically_normal() == files[i].path.lexically_normal())
        throw IoError("cannot write " + files[i].path.string() + " twice: two outputs name the same file");
  }
  std::vector<std::unique_ptr<AtomicOutput>> outs;
  for (const FileContent& f : files) {
    outs.push_back(std::make_unique<AtomicOutput>(f.path));
    writeTemporary(*outs.back(), f.path, f.content);
  }
  for (auto& out : outs) out->commit();
}

void ensureDirectory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw IoError("cannot create directory " + dir.string() + (ec ? ": " + ec.message() : ""));
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
