#include "conformance/io/timevarying_file.h"

#include "reference/common/byte_stream.h"

namespace voxref::io {

ref::TimeVaryingFile readTimeVarying(const std::filesystem::path& path) {
  const std::string bytes = readWholeFile(path);
  try {
    return ref::parseTimeVarying(bytes);
  } catch (const ref::StreamError& e) {
    throw FormatError(path.string() + ": " + e.what());
  }
}

void writeTimeVarying(const std::filesystem::path& path, const ref::TimeVaryingFile& file) {
  writeFileAtomically(path, ref::serializeTimeVarying(file));
}

}  // namespace voxref::io
