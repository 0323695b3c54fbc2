#include "conformance/io/leb_file.h"

#include <fstream>
#include <sstream>

#include "reference/common/byte_stream.h"

namespace voxref::io {

ref::LebStream readLebFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw IoError(path.string() + " does not exist");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open " + path.string());
  std::ostringstream ss;
  ss << in.rdbuf();
  try {
    return ref::parseLebStream(std::move(ss).str());
  } catch (const ref::StreamError& e) {
    throw FormatError(path.string() + ": " + e.what());
  }
}

void writeLebFile(const std::filesystem::path& path, const std::string& stream) { writeFileAtomically(path, stream); }

}  // namespace voxref::io
