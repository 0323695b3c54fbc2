// Files of the time-varying codec (.vxtv): the container of reference/timevarying/FORMAT.md, read
// whole and parsed, written atomically (atomic_file.h); as leb_file.h is for the LEB stream.
#pragma once

#include <filesystem>

#include "conformance/io/atomic_file.h"
#include "reference/timevarying/container.h"

namespace voxref::io {

// Throws IoError when the file is missing or unreadable, FormatError ("<file>: offset N: <field>:
// ...") when the container is corrupt.
ref::TimeVaryingFile readTimeVarying(const std::filesystem::path& path);
// Throws std::invalid_argument for textures the format cannot hold (nothing is written), IoError
// when the file cannot be written.
void writeTimeVarying(const std::filesystem::path& path, const ref::TimeVaryingFile& file);

}  // namespace voxref::io
