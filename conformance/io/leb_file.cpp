#include "conformance/io/leb_file.h"

#include <fstream>
#include <sstream>

#include "reference/common/byte_stream.h"

namespace voxref::io {

ref::LebStream readLebFile(const std::filesystem::path& path) {
  std::string bytes = readWholeFile(path);
  try {
    return ref::parseLebStream(std::move(bytes));
  } catch (const ref::StreamError& e) {
    throw FormatError(path.string() + ": " + e.what());
  }
}

void writeLebFile(const std::filesystem::path& path, const std::string& stream) { writeFileAtomically(path, stream); }

}  // namespace voxref::io
