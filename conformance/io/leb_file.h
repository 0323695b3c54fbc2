// Files of the LEB codec (.vxleb): the stream of reference/leb/FORMAT.md, read whole and parsed,
// written atomically (atomic_file.h).
#pragma once

#include <filesystem>
#include <string>

#include "conformance/io/atomic_file.h"
#include "reference/leb/leb_stream.h"

namespace voxref::io {

// Throws IoError when the file is missing or unreadable, FormatError ("<file>: offset N: <field>:
// ...") when the stream is corrupt.
ref::LebStream readLebFile(const std::filesystem::path& path);
void writeLebFile(const std::filesystem::path& path, const std::string& stream);

}  // namespace voxref::io
