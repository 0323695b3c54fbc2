// Image files: 8-bit PNG previews (OpenImageIO) and float EXR results (OpenEXR). Both are
// written atomically (atomic_file.h); failures throw IoError naming the file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace voxref::io {

// 8-bit RGB, row 0 at the TOP (file order).
struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

void writePng(const std::filesystem::path& path, const Rgb8Image& image);

struct ExrChannel {
  std::string name;                          // e.g. "Y", "Z", "R"
  std::vector<float> data;                   // width * height, row 0 at the TOP
  std::vector<std::uint32_t> uintData = {};  // instead of data: a 32-bit UINT channel (ids)
};

// A scanline EXR of 32-bit float (or UINT) channels, with string attributes (scene, backend,
// version). ZIP compression; the bytes depend only on the inputs (no time stamps).
void writeExr(const std::filesystem::path& path, int width, int height, const std::vector<ExrChannel>& channels,
              const std::map<std::string, std::string>& attributes);

}  // namespace voxref::io
