// SHA-256 of bytes or of a file, as lower-case hex (OpenSSL's libcrypto, FIPS 180-4). Used by the
// fixture manifest (fixtures/). Throws IoError naming a file that cannot be read.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace voxref::io {

std::string sha256Hex(std::string_view bytes);
std::string sha256OfFile(const std::filesystem::path& path);

}  // namespace voxref::io
