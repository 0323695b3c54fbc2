// libFuzzer target: raw volume files (conformance/io/raw_volume.h): headerless voxels, plain or
// gzip-compressed, read against the dimensions the caller gives (`voxref encode --dims`, scene
// files' "dims", fixture manifests' "dims": all untrusted).
//
// Input: byte 0 bit 0 selects uint8 or uint16 voxels; bytes 1..12 are the dimensions, three
// little-endian int32 (any value: zero, negative and huge ones included); the rest is the file's
// content, written to a temporary file: readRawVolume* only reads files, and it reads them through
// zlib's gzopen/gzread, which decompress a gzip stream and pass plain bytes through whatever the
// file is called, so mutations reach both paths.
// Contract under test:
// - readRawVolumeU8 / readRawVolumeU16 either return a volume of exactly the dimensions and the
//   file's voxels, or throw io::IoError (not valid gzip, a truncated gzip stream, a size other than
//   the dimensions need, dimensions that are not a volume: an extent below 1 or more than 2^40
//   voxels); nothing else escapes, nothing reads out of bounds (ASan), no undefined behaviour
//   (UBSan);
// - memory follows the file, not the dimensions: a file of a few bytes claiming a huge volume
//   is refused without allocating for that volume (libFuzzer's -rss_limit_mb and -malloc_limit_mb
//   catch an allocation driven by the claimed size).
// Size cap: none; the content is as long as libFuzzer's -max_len allows (gzip can expand it; the
// reader stops at the expected size + 1).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "conformance/io/atomic_file.h"
#include "conformance/io/raw_volume.h"
#include "reference/common/byte_stream.h"

namespace {

const std::filesystem::path& scratchFile() {
  static const std::filesystem::path p =
      std::filesystem::temp_directory_path() / ("voxref-raw-volume-fuzz-" + std::to_string(::getpid()) + ".raw");
  static const bool cleanup = [] { return std::atexit([] { std::filesystem::remove(scratchFile()); }) == 0; }();
  (void)cleanup;
  return p;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voxref;
  if (size < 13) return 0;
  const char* bytes = reinterpret_cast<const char*>(data);
  const bool sixteen = data[0] & 1;
  ref::Dims3 dims{};
  for (int a = 0; a < 3; ++a)
    dims[static_cast<std::size_t>(a)] =
        static_cast<std::int32_t>(static_cast<std::uint32_t>(ref::loadLe(bytes + 1 + 4 * a, 4)));
  {
    std::ofstream out(scratchFile(), std::ios::binary | std::ios::trunc);
    out.write(bytes + 13, static_cast<std::streamsize>(size - 13));
    if (!out) std::abort();
  }
  // Without gzip's magic number the file is read as it is: the voxels are its bytes.
  const std::string_view content(bytes + 13, size - 13);
  const bool plain = content.size() < 2 || content.substr(0, 2) != "\x1f\x8b";
  try {
    if (sixteen) {
      const ref::Volume<std::uint16_t> v = io::readRawVolumeU16(scratchFile(), dims);
      if (v.dims() != dims || v.data().size() != ref::sampleCount(dims)) std::abort();
      if (plain)
        for (std::size_t i = 0; i < v.data().size(); ++i)
          if (v.data()[i] != ref::loadLe(content.data() + 2 * i, 2)) std::abort();
    } else {
      const ref::Volume<std::uint8_t> v = io::readRawVolumeU8(scratchFile(), dims);
      if (v.dims() != dims || v.data().size() != ref::sampleCount(dims)) std::abort();
      if (plain && std::string_view(reinterpret_cast<const char*>(v.data().data()), v.data().size()) != content)
        std::abort();
    }
  } catch (const io::IoError&) {
  }
  return 0;
}
