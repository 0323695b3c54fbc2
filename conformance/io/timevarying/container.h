// The `.vxtv` container of time-varying textures: FORMAT.md beside this file is its definition.
//
// parseTimeVarying is safe on untrusted bytes: every field is checked before it is used and
// before anything is allocated for it; errors are FormatError, naming the file, the byte offset
// and what was expected. Writing is atomic (atomic_file.h).
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
  ref::AlphaOnePolicy alphaOne = ref::AlphaOnePolicy::Refine;
};

std::string serializeTimeVarying(const TimeVaryingFile& file);
TimeVaryingFile parseTimeVarying(std::string_view bytes, const std::string& sourceName);

void writeTimeVarying(const std::filesystem::path& path, const TimeVaryingFile& file);
TimeVaryingFile readTimeVarying(const std::filesystem::path& path);  // IoError if unreadable

}  // namespace voxref::io
