// Writing files so that nothing is ever half-written: the content goes to a temporary file in
// the same directory, which is renamed over the destination only when complete.
//
// Destinations that are not regular files are never replaced (docs/bad_input.md, "Outputs that
// are not regular files"): a character device or a FIFO (`--out /dev/null`, a named pipe) is
// written through, as `cp` and `zstd -o` do; such a write cannot be atomic (a reader of the pipe
// sees the bytes as they come, and a failure part way leaves what was written). A directory, a
// block device, a socket or any other kind of file is refused with an IoError naming it. A
// symbolic link is followed: its target is written (atomically when it is a regular file) and
// the link stays.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "conformance/io/temporary_files.h"

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

// How an output path is written: Atomic (a regular file, or nothing there yet: temporary file
// and rename) or Stream (a character device or FIFO: written through). Throws IoError for a
// directory, a block device, a socket or another kind of file, naming the path and its kind.
enum class OutputKind { Atomic, Stream };
OutputKind outputKind(const std::filesystem::path& destination);

// A temporary path beside `destination` ("<name>.tmp<pid>.<ext>", keeping the extension so that
// format libraries recognise it). commit() renames it onto the destination; the destructor
// removes it if commit() was not reached, and so does SIGINT, SIGTERM or SIGHUP once
// removeTemporariesOnSignals() has run (temporary_files.h). For a Stream destination the temporary lies in the
// system's temporary folder and commit() copies it into the stream (not atomic, see above).
// Throws IoError as outputKind() does.
class AtomicOutput {
 public:
  explicit AtomicOutput(std::filesystem::path destination);
  AtomicOutput(const AtomicOutput&) = delete;
  AtomicOutput& operator=(const AtomicOutput&) = delete;
  ~AtomicOutput();
  const std::filesystem::path& temporary() const { return temporary_; }
  void commit();  // throws IoError

 private:
  std::filesystem::path destination_;
  OutputKind kind_;
  std::filesystem::path temporary_;
  TemporaryFileGuard guard_;  // destroyed after the destructor's removal
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

// A folder made empty now and removed with everything in it when this goes out of scope, whatever
// happens in between (a staging or scratch folder). Throws IoError when it cannot be made.
class TemporaryFolder {
 public:
  explicit TemporaryFolder(std::filesystem::path dir);
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  ~TemporaryFolder();
  const std::filesystem::path& path() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

}  // namespace voxref::io
