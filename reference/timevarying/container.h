// The `.vxtv` container of time-varying textures, as bytes: FORMAT.md beside this file is its
// definition (files of it: conformance/io/timevarying_file.h, as the LEB stream's are
// conformance/io/leb_file.h).
//
// parseTimeVarying is safe on untrusted bytes: every field is checked before it is used and
// before anything is allocated for it; errors are StreamError (reference/common/byte_stream.h),
// naming the byte offset and what was expected.
//
// Memory: parseTimeVarying allocates at most 5 times the size of the bytes it is given (the index
// texels widened to 32 bits each, 4 bytes per stored channel byte at most, and a copy of the
// refinement texels), and only after the sizes the header claims have been checked against the
// length of the bytes: a header that claims terabytes of texture over a small file is refused
// before anything is allocated for it. conformance/io/timevarying_file.h adds the file's bytes. Decoding a time step
// (ref::decodeStep) allocates that step's voxels in their original extents, 4 bytes each (at most
// 512^3 x 4 = 512 MiB: the format's extents are at most its largest side, 512).
#pragma once

#include <string>
#include <string_view>

#include "reference/timevarying/timevarying_codec.h"
#include "reference/timevarying/transfer_function.h"

namespace voxref::ref {

struct TimeVaryingFile {
  TimeVaryingTextures textures;
  TransferFunction transfer;
};

// The container's bytes. Throws std::invalid_argument when the textures exceed what the format
// holds (FORMAT.md section 1: time_steps 1..65536, ...): voxref never writes a file it cannot read.
std::string serializeTimeVarying(const TimeVaryingFile& file);
// Throws StreamError ("offset N: <field>: expected ...").
TimeVaryingFile parseTimeVarying(std::string_view bytes);

}  // namespace voxref::ref
