#include "conformance/io/raw_volume.h"

#include <zlib.h>

#include <cstring>
#include <vector>

#include "conformance/io/atomic_file.h"

namespace voxref::io {
namespace {

// All bytes of the file (decompressed for .gz), refusing to read more than `expected` + 1 so that a
// huge or endless stream is never held in memory.
std::vector<unsigned char> readBytes(const std::filesystem::path& path, std::size_t expected) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw IoError("volume file " + path.string() + " does not exist");
  gzFile f = gzopen(path.c_str(), "rb");  // reads plain files transparently
  if (!f) throw IoError("cannot open volume file " + path.string() + ": " + std::strerror(errno));
  // Grow while reading, so that claimed dimensions larger than the file allocate nothing extra.
  std::vector<unsigned char> bytes;
  std::size_t total = 0;
  constexpr std::size_t kChunk = std::size_t{1} << 24;
  while (total <= expected) {
    bytes.resize(std::min(total + kChunk, expected + 1));
    const unsigned want = static_cast<unsigned>(bytes.size() - total);
    const int n = gzread(f, bytes.data() + total, want);
    if (n < 0) {
      int errnum = 0;
      const std::string msg = gzerror(f, &errnum);
      gzclose(f);
      throw IoError("volume file " + path.string() + " is corrupt after " + std::to_string(total) + " bytes: " + msg);
    }
    total += static_cast<std::size_t>(n);
    if (static_cast<unsigned>(n) < want) break;
  }
  gzclose(f);
  if (total != expected)
    throw IoError("volume file " + path.string() + " holds " + (total > expected ? "more than " : "") +
                  std::to_string(total > expected ? expected : total) + " bytes; the dimensions need " +
                  std::to_string(expected));
  bytes.resize(total);
  return bytes;
}

}  // namespace

std::optional<VoxelType> parseVoxelType(std::string_view s) {
  if (s == "uint8") return VoxelType::UInt8;
  if (s == "uint16") return VoxelType::UInt16;
  return std::nullopt;
}

ref::Volume<std::uint8_t> readRawVolumeU8(const std::filesystem::path& path, const ref::Dims3& dims) {
  const std::size_t n = ref::sampleCount(dims);
  std::vector<unsigned char> bytes = readBytes(path, n);
  return ref::Volume<std::uint8_t>(dims, std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
}

ref::Volume<std::uint16_t> readRawVolumeU16(const std::filesystem::path& path, const ref::Dims3& dims) {
  const std::size_t n = ref::sampleCount(dims);
  const std::vector<unsigned char> bytes = readBytes(path, n * 2);
  std::vector<std::uint16_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint16_t>(bytes[2 * i] | (bytes[2 * i + 1] << 8));
  return ref::Volume<std::uint16_t>(dims, std::move(v));
}

}  // namespace voxref::io
