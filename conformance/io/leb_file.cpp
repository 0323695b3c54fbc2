#include "conformance/io/leb_file.h"

#include "reference/common/byte_stream.h"

namespace voxref::io {

LebFile openLebFile(const std::filesystem::path& path) {
  LebFile f;
  f.file = std::make_shared<MappedFile>(MappedFile::openRead(path));
  try {
    f.stream = ref::parseLebStream(f.file->bytes(), f.file);
  } catch (const ref::StreamError& e) {
    throw FormatError(path.string() + ": " + e.what());
  }
  return f;
}

ref::LebStream readLebFile(const std::filesystem::path& path) { return openLebFile(path).stream; }

void writeLebFile(const std::filesystem::path& path, const std::string& stream) { writeFileAtomically(path, stream); }

}  // namespace voxref::io
