// The LEB codec between files in bounded memory (Gregorski et al. 2004 compress volumes far larger
// than memory; reference/leb/leb_codec.h does the work): the volume, its gradients and the stream
// are file mappings (mapped_file.h), trimmed whenever their resident pages exceed the window, so
// what stays resident is the window, the shell of padding and one batch of pages, not the volume.
// Outputs are written beside their destinations and renamed into place when complete
// (atomic_file.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string_view>

#include "conformance/io/leb_file.h"
#include "conformance/io/raw_volume.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/mirror_fold.h"

namespace voxref::io {

// The resident pages of file mappings past which mappings are trimmed, unless the caller says
// otherwise (ResidentWindow).
inline constexpr std::uint64_t kLebWindowBytes = std::uint64_t{512} << 20;

// Told how far a long step has come: the fraction of its work (0..1) and what it is doing.
using LebProgress = std::function<void(double done, std::string_view step)>;

struct LebFileRun {
  std::uint64_t streamBytes = 0;        // of the stream written (encode) or read (decode)
  int trims = 0;                        // how often the window trimmed the mappings
  ref::LebMirrorPlanes mirrorPlanes{};  // encode: the planes the volume was folded across (none: not folded)
  std::uint64_t mirrorExceptions = 0;   // encode with mirror planes: the points that differ from their image
};

// How encodeLebFile folds the volume (reference/leb/mirror_fold.h): across `planes` (none: not at
// all), or with `find` across those ref::findLebMirrorPlanes finds, with the gradients when they
// are stored (they are folded too).
struct LebFileMirror {
  bool find = false;
  ref::LebMirrorPlanes planes;
};

// Encodes the raw volume `input` (x fastest, uint8 or uint16 little endian; a ".gz" input is
// inflated into memory first, the one case where the volume is held) into the stream `out`.
// The gradients (quantizedGradients, made slice by slice) go to a temporary file beside `out`,
// removed afterwards. Throws IoError naming the file (missing, wrong size, disk full: "cannot
// write <out>: <reason>", and nothing is left at `out`), std::invalid_argument as encodeLeb.
// With mirror planes (given or found) the stream is a mirrored one (reference/leb/mirror_stream.h):
// the folded volume, and its gradients when stored, go to temporary files beside `out`
// (foldLebVolume, one pass), and are encoded from there; std::invalid_argument then also as
// encodeMirroredLebTo and foldLebVolume (too many exceptions).
LebFileRun encodeLebFile(const std::filesystem::path& input, const ref::Dims3& dims, VoxelType type,
                         const std::filesystem::path& out, const ref::LebEncodeOptions& options,
                         std::uint64_t window = kLebWindowBytes, const LebProgress& progress = {},
                         const LebFileMirror& mirror = {});
// The address space encodeLebFile maps and allocates, from the extents (for a refusal under
// ulimit -v before anything is read): the volume and its gradients mapped, and what the encoder
// allocates (ref::lebEncodeToMemoryBytes).
std::uint64_t lebFileEncodeAddressBytes(const ref::Dims3& dims, VoxelType type, const ref::LebEncodeOptions& options);

// Decodes the stream of `input` (openLebFile) into the raw volume `out` (uint8, or uint16 little endian) and, when
// `gradientsOut` is not empty, its gradients (3 int8 per sample); both are renamed into place only
// when both are complete. A stream's gradients are decoded (and so checked) even when they are not
// asked for, into a temporary file removed afterwards. Throws IoError naming the file, FormatError
// "<input>: offset N: ..." for a corrupt stream, std::invalid_argument when gradients are asked of
// a stream without them.
LebFileRun decodeLebFile(const LebFile& input, const std::filesystem::path& out,
                         const std::filesystem::path& gradientsOut, int threads = 0,
                         std::uint64_t window = kLebWindowBytes, const LebProgress& progress = {});
// The same for a mirrored stream: the folded volume is decoded into the start of the samples'
// file (its gradients, when stored, into the start of theirs) and unfolded in place
// (ref::decodeMirroredLebInto); derived gradients are computed after.
LebFileRun decodeLebFile(const MirroredLebFile& input, const std::filesystem::path& out,
                         const std::filesystem::path& gradientsOut, int threads = 0,
                         std::uint64_t window = kLebWindowBytes, const LebProgress& progress = {});
// The address space decodeLebFile maps and allocates for `stream`: the stream, the volume and its
// gradients mapped, and the shells of padding (one a channel); for a mirrored stream, its
// exceptions too.
std::uint64_t lebFileDecodeAddressBytes(const ref::LebStream& stream);
std::uint64_t lebFileDecodeAddressBytes(const ref::MirroredLebStream& stream);

}  // namespace voxref::io
