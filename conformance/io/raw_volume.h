// Raw volume files: a headerless array of voxels, x fastest (the layout of
// ../shared/data/volumes/SOURCES.md), optionally gzip-compressed (".gz").
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>

#include "reference/common/volume.h"

namespace voxref::io {

enum class VoxelType { UInt8, UInt16 };
std::optional<VoxelType> parseVoxelType(std::string_view s);

// Reads exactly X*Y*Z voxels of `type` (uint16 little endian). Throws IoError naming the file
// when it is missing, unreadable, not valid gzip, or holds a different number of bytes than the
// dimensions need (the message gives both counts). The size is checked against the file (or the
// gzip stream) before the volume is allocated beyond that size. Safe on untrusted input.
ref::Volume<std::uint8_t> readRawVolumeU8(const std::filesystem::path& path, const ref::Dims3& dims);
ref::Volume<std::uint16_t> readRawVolumeU16(const std::filesystem::path& path, const ref::Dims3& dims);

}  // namespace voxref::io
