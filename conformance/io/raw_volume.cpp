#include "conformance/io/raw_volume.h"

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "conformance/io/atomic_file.h"

namespace voxref::io {
namespace {

constexpr std::size_t kFirstChunk = std::size_t{1} << 16, kMaxChunk = std::size_t{1} << 24;

// Room for the next read: twice what has been read (64 KiB at first, by at most 16 MiB at a time),
// never beyond `limit`.
void grow(std::vector<unsigned char>& bytes, std::size_t total, std::size_t limit) {
  bytes.resize(std::min(total + std::clamp(total, kFirstChunk, kMaxChunk), limit));
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw IoError("volume file " + path.string() + " " + what);
}

// All bytes of the file (decompressed when it starts with the gzip magic), refusing to read more
// than `expected` + 1 so that a huge or endless stream is never held in memory. The buffer grows
// with what has been read (grow()), so that claimed dimensions larger than the file allocate at
// most 64 KiB or twice what the file holds, never the claimed size. A gzip stream must end with
// its trailer (its CRC-32 and length checked by zlib); a file that stops before is truncated.
std::vector<unsigned char> readBytes(const std::filesystem::path& path, std::size_t expected) {
  requireVolumeFile(path);
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw IoError("cannot open volume file " + path.string() + ": " + std::strerror(errno));
  struct Closer {
    void operator()(std::FILE* file) const { std::fclose(file); }
  };
  const std::unique_ptr<std::FILE, Closer> closer(f);
  auto readError = [&] { fail(path, std::string("cannot be read: ") + std::strerror(errno)); };
  const std::size_t limit = expected + 1;  // one byte more than needed tells a file that is too long
  std::vector<unsigned char> bytes;
  std::size_t total = 0;
  unsigned char magic[2] = {0, 0};
  const bool gzip = std::fread(magic, 1, 2, f) == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
  if (std::ferror(f) || std::fseek(f, 0, SEEK_SET) != 0) readError();
  if (!gzip) {
    while (total < limit) {
      if (total == bytes.size()) grow(bytes, total, limit);
      const std::size_t n = std::fread(bytes.data() + total, 1, bytes.size() - total, f);
      total += n;
      if (n == 0) {
        if (std::ferror(f)) readError();
        break;
      }
    }
  } else {
    z_stream z{};
    if (inflateInit2(&z, 15 + 16) != Z_OK) fail(path, "cannot be decompressed: zlib failed to start");
    struct Ender {
      void operator()(z_stream* stream) const { inflateEnd(stream); }
    };
    const std::unique_ptr<z_stream, Ender> ender(&z);
    std::vector<unsigned char> in(kFirstChunk);
    std::uint64_t fileRead = 0;
    bool eof = false, ended = false;  // ended: at the end of a gzip member (its trailer checked)
    while (total < limit) {
      if (z.avail_in == 0 && !eof) {
        const std::size_t n = std::fread(in.data(), 1, in.size(), f);
        if (n == 0 && std::ferror(f)) readError();
        eof = n == 0;
        fileRead += n;
        z.next_in = in.data();
        z.avail_in = static_cast<uInt>(n);
      }
      if (ended) {  // gzip allows members one after the other; anything else is an error below
        if (z.avail_in == 0) {
          if (eof) break;
          continue;
        }
        inflateReset(&z);
        ended = false;
      }
      if (total == bytes.size()) grow(bytes, total, limit);
      z.next_out = bytes.data() + total;
      z.avail_out = static_cast<uInt>(bytes.size() - total);
      const int r = inflate(&z, Z_NO_FLUSH);
      total = bytes.size() - z.avail_out;
      if (r == Z_STREAM_END) {
        ended = true;
      } else if (r == Z_BUF_ERROR && z.avail_in == 0 && eof) {
        break;  // the file ends inside the gzip stream
      } else if (r != Z_OK && r != Z_BUF_ERROR) {
        std::string why = z.msg ? z.msg : "invalid gzip data";
        if (why == "incorrect data check") why += " (the CRC-32 in the gzip trailer does not match the data)";
        if (why == "incorrect length check") why += " (the length in the gzip trailer does not match the data)";
        fail(path, "is corrupt at byte " + std::to_string(fileRead - z.avail_in) + " of its gzip stream, after " +
                       std::to_string(total) + " bytes of data: " + why);
      }
    }
    if (total < limit && !ended)
      fail(
          path,
          "is a truncated gzip stream: the file ends after " + std::to_string(total) +
              " bytes of data, before the gzip trailer (CRC-32 and length) that ends the stream; the dimensions need " +
              std::to_string(expected));
  }
  requireVolumeSize(path, total, expected);
  bytes.resize(total);
  return bytes;
}

}  // namespace

void requireVolumeFile(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    fail(path, std::filesystem::exists(path, ec) ? "is not a regular file" : "does not exist");
}

void requireVolumeSize(const std::filesystem::path& path, std::uint64_t bytes, std::uint64_t need) {
  if (bytes != need)
    fail(path, "holds " + std::string(bytes > need ? "more than " : "") + std::to_string(bytes > need ? need : bytes) +
                   " bytes; the dimensions need " + std::to_string(need));
}

bool isGzipFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char magic[2] = {0, 0};
  in.read(reinterpret_cast<char*>(magic), 2);
  return in.gcount() == 2 && magic[0] == 0x1f && magic[1] == 0x8b;
}

std::size_t voxelsOf(const std::filesystem::path& path, const ref::Dims3& dims) {
  try {
    return ref::sampleCount(dims);
  } catch (const std::invalid_argument& e) {
    throw IoError("volume file " + path.string() + ": the dimensions are out of range: " + e.what());
  }
}

std::optional<VoxelType> parseVoxelType(std::string_view s) {
  if (s == "uint8") return VoxelType::UInt8;
  if (s == "uint16") return VoxelType::UInt16;
  return std::nullopt;
}

ref::Volume<std::uint8_t> readRawVolumeU8(const std::filesystem::path& path, const ref::Dims3& dims) {
  const std::size_t n = voxelsOf(path, dims);
  std::vector<unsigned char> bytes = readBytes(path, n);
  return ref::Volume<std::uint8_t>(dims, std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
}

ref::Volume<std::uint16_t> readRawVolumeU16(const std::filesystem::path& path, const ref::Dims3& dims) {
  const std::size_t n = voxelsOf(path, dims);
  const std::vector<unsigned char> bytes = readBytes(path, n * 2);
  std::vector<std::uint16_t> v(n);
  for (std::size_t i = 0; i < n; ++i) v[i] = static_cast<std::uint16_t>(bytes[2 * i] | (bytes[2 * i + 1] << 8));
  return ref::Volume<std::uint16_t>(dims, std::move(v));
}

}  // namespace voxref::io
