// CRC-32 (ISO-HDLC: polynomial 0x04C11DB7 reflected, initial and final XOR 0xFFFFFFFF), the
// checksum of zlib, gzip and PNG. Streams voxref writes carry it so that corruption is reported,
// not decoded. crc32Update continues a checksum over more bytes: crc32(a + b) ==
// crc32Update(crc32(a), b).
//
// Speed: where the CPU multiplies without carries (x86-64's PCLMULQDQ, asked at run time), a
// message of 64 bytes or more is folded 64 bytes a step (crc32.cpp); otherwise, and for shorter
// messages, eight bytes a step by tables. Both give the same value (crc32_paths.h names them for
// the tests).
#pragma once

#include <cstdint>
#include <string_view>

namespace voxref::ref {

std::uint32_t crc32Update(std::uint32_t crc, std::string_view bytes);
inline std::uint32_t crc32(std::string_view bytes) { return crc32Update(0, bytes); }

// Whether the CRC-32 of `bytes` is `stored`. Fuzz builds (FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION,
// the macro libFuzzer's users agree on) accept every checksum, so that mutated inputs reach the
// parsers and decoders behind the checksums instead of stopping at them.
inline bool crc32Matches(std::string_view bytes, std::uint32_t stored) {
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
  (void)crc32(bytes);
  (void)stored;
  return true;
#else
  return crc32(bytes) == stored;
#endif
}

}  // namespace voxref::ref
