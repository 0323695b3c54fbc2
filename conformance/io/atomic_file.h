// Writing files so that nothing is ever half-written: the content goes to a temporary file in
// the same directory, which is renamed over the destination only when complete.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace voxref::io {

// Any failure to read or write a file; the message names the file and the reason.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A file whose content is not what its format allows; the message names the file, the byte
// offset and what was expected.
class FormatError : public IoError {
 public:
  using IoError::IoError;
};

// A temporary path beside `destination` ("<name>.tmp<pid>.<ext>", keeping the extension so that
// format libraries recognise it). commit() renames it onto the destination; the destructor
// removes it if commit() was not reached.
class AtomicOutput {
 public:
  explicit AtomicOutput(std::filesystem::path destination);
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  ~AtomicOutput();
  const std::filesystem::path& temporary() const { return temporary_; }
  void commit();  // throws IoError

 private:
  std::filesystem::path destination_, temporary_;
  bool committed_ = false;
};

// Throws IoError naming the path (directory missing, disk full, permission).
void writeFileAtomically(const std::filesystem::path& path, std::string_view content);

// Several files that belong together (a stream and its side file): every one is written to its
// temporary first, and they are renamed onto their destinations only when all are complete, so a
// failure leaves none of them (and every earlier file at those paths as it was). Throws IoError.
struct FileContent {
  std::filesystem::path path;
  std::string_view content;
};
void writeFilesAtomically(const std::vector<FileContent>& files);

// The whole content of a regular file; throws IoError "<path> does not exist", "<path> is not a
// regular file" or "cannot open". Memory: the file's size (the caller's parser bounds the rest).
std::string readWholeFile(const std::filesystem::path& path);

// Creates the directory (and parents); throws IoError naming it.
void ensureDirectory(const std::filesystem::path& dir);

}  // namespace voxref::io
