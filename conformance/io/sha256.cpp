#include "conformance/io/sha256.h"

#include <openssl/evp.h>

#include <array>
#include <stdexcept>

#include "conformance/io/atomic_file.h"

namespace voxref::io {

std::string sha256Hex(std::string_view bytes) {
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), digest.data(), &length, EVP_sha256(), nullptr) != 1)
    throw std::runtime_error("SHA-256: EVP_Digest failed");
  static constexpr char kHex[] = "0123456789abcdef";
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) {
    hex.push_back(kHex[digest[i] >> 4]);
    hex.push_back(kHex[digest[i] & 15]);
  }
  return hex;
}

std::string sha256OfFile(const std::filesystem::path& path) { return sha256Hex(readWholeFile(path)); }

}  // namespace voxref::io
