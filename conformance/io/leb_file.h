// Files of the LEB codec (.vxleb): the stream of reference/leb/FORMAT.md, mapped (mapped_file.h)
// and parsed, written atomically (atomic_file.h).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <variant>

#include "conformance/io/atomic_file.h"
#include "conformance/io/mapped_file.h"
#include "reference/leb/leb_stream.h"
#include "reference/leb/mirror_stream.h"

namespace voxref::io {

// A stream file mapped and parsed: `stream` views the mapping, which `file` (and the stream's
// owner) keeps; parsing touches the header and the page tables only. Throws IoError when the file
// is missing or unreadable, FormatError ("<file>: offset N: <field>: ...") when the stream is
// corrupt, and for a mirrored stream (openAnyLebFile reads those).
struct LebFile {
  std::shared_ptr<MappedFile> file;
  ref::LebStream stream;
};
LebFile openLebFile(const std::filesystem::path& path);
// A mirrored stream (reference/leb/mirror_stream.h) mapped and parsed, as LebFile.
struct MirroredLebFile {
  std::shared_ptr<MappedFile> file;
  ref::MirroredLebStream stream;
};
// Either kind, as the file's magic says. Throws as openLebFile, and FormatError for a corrupt
// mirrored stream.
std::variant<LebFile, MirroredLebFile> openAnyLebFile(const std::filesystem::path& path);
// openLebFile(path).stream.
ref::LebStream readLebFile(const std::filesystem::path& path);
void writeLebFile(const std::filesystem::path& path, const std::string& stream);

}  // namespace voxref::io
