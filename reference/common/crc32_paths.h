// The two ways crc32Update computes the CRC-32 (crc32.h), named for the tests that compare them
// with each other and with the bitwise definition: slicedUpdate always by tables (slicing-by-8),
// foldedUpdate by carry-less multiplication where foldedAvailable() (else as slicedUpdate).
// crc32Update is foldedUpdate. Not for callers: crc32.h is the interface.
#pragma once

#include <cstdint>
#include <string_view>

namespace voxref::ref::crc32_detail {

std::uint32_t slicedUpdate(std::uint32_t crc, std::string_view bytes);
std::uint32_t foldedUpdate(std::uint32_t crc, std::string_view bytes);
bool foldedAvailable();

}  // namespace voxref::ref::crc32_detail
