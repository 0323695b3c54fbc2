// The `.vxtv` container of time-varying textures: FORMAT.md beside this file is its definition.
//
// parseTimeVarying is safe on untrusted bytes: every field is checked before it is used and
// before anything is allocated for it; errors are FormatError, naming the file, the byte offset
// and what was expected. Writing is atomic (atomic_file.h).
//
// Memory: parseTimeVarying allocates at most 5 times the size of the bytes it is given (the index
// texels widened to 32 bits each, 4 bytes per stored channel byte at most, and a copy of the
// refinement texels), and only after the sizes the header claims have been checked against the
// length of the bytes: a header that claims terabytes of texture over a small file is refused
// before anything is allocated for it. readTimeVarying adds the file's bytes. Decoding a time step
// (ref::decodeStep) allocates that step's voxels in their original extents, 4 bytes each (at most
// 512^3 x 4 = 512 MiB: the format's extents are at most its largest side, 512).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "conformance/io/atomic_file.h"
#include "reference/timevarying/timevarying_codec.h"

namespace voxref::io {

struct TimeVaryingFile {
  ref::TimeVaryingTextures textures;
  ref::TransferFunction transfer;
};

// The container's bytes. Throws std::invalid_argument when the textures exceed what the format
// holds (FORMAT.md section 1: time_steps 1..65536, ...): voxref never writes a file it cannot read.
std::string serializeTimeVarying(const TimeVaryingFile& file);
TimeVaryingFile parseTimeVarying(std::string_view bytes, const std::string& sourceName);

void writeTimeVarying(const std::filesystem::path& path, const TimeVaryingFile& file);
TimeVaryingFile readTimeVarying(const std::filesystem::path& path);  // IoError if unreadable

}  // namespace voxref::io
