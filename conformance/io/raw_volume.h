// Raw volume files: a headerless array of voxels, x fastest (the layout of the real CT and
// simulation volumes the tests and the bench read), optionally gzip-compressed (".gz").
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
// when it is missing, not a regular file, unreadable, not valid gzip, a truncated gzip stream,
// holds a different number of bytes than the dimensions need (the message gives both counts), or
// when the dimensions are not positive or exceed 2^40 voxels. The size is checked against the file
// (or the gzip stream) before the volume is allocated beyond that size. Safe on untrusted input.
//
// Memory: the read buffer, at most the dimensions' size plus one byte and at most twice what has
// been read so far (64 KiB to start, growing by at most 16 MiB at a time), plus the returned
// volume once the size has matched. Reading stops one byte past the size the dimensions need, so
// dimensions of 65535^3 over a small file, or a gzip that would expand beyond the dimensions, are
// refused after allocating at most 64 KiB or twice the data actually there, never the claimed size.
// The number of voxels of the dimensions of `path`; IoError naming the file when they are not
// positive or exceed ref::sampleCount's limit. Nothing is read: the readers check this first, and a
// caller that must size its work before reading (voxref encode --codec leb) calls it itself.
std::size_t voxelsOf(const std::filesystem::path& path, const ref::Dims3& dims);

// Throws IoError "volume file <path> does not exist" or "... is not a regular file": the readers'
// first check, and that of the LEB codec, which maps raw volumes (leb_file_codec.h).
void requireVolumeFile(const std::filesystem::path& path);
// Throws IoError "volume file <path> holds N bytes; the dimensions need M" ("holds more than M"
// when longer) unless `bytes` == `need`: the readers' size check, and the LEB file codec's.
void requireVolumeSize(const std::filesystem::path& path, std::uint64_t bytes, std::uint64_t need);
// Whether the file's first bytes are gzip's magic (1f 8b): the readers inflate such a file.
bool isGzipFile(const std::filesystem::path& path);

ref::Volume<std::uint8_t> readRawVolumeU8(const std::filesystem::path& path, const ref::Dims3& dims);
ref::Volume<std::uint16_t> readRawVolumeU16(const std::filesystem::path& path, const ref::Dims3& dims);

}  // namespace voxref::io
