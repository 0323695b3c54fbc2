// CRC-32 (ISO-HDLC: polynomial 0x04C11DB7 reflected, initial and final XOR 0xFFFFFFFF), the
// checksum of zlib, gzip and PNG. Streams voxref writes carry it so that corruption is reported,
// not decoded. crc32Update continues a checksum over more bytes: crc32(a + b) ==
// crc32Update(crc32(a), b).
#pragma once

#include <cstdint>
#include <string_view>

namespace voxref::ref {

std::uint32_t crc32Update(std::uint32_t crc, std::string_view bytes);
inline std::uint32_t crc32(std::string_view bytes) { return crc32Update(0, bytes); }

}  // namespace voxref::ref
