// libFuzzer target: the time-varying container reader (reference/timevarying/container.h,
// reference/timevarying/FORMAT.md beside it) on arbitrary bytes, then the exact decoder on whatever it accepts.
//
// Contract under test:
// - parseTimeVarying either returns or throws io::FormatError; nothing else escapes, and nothing
//   reads or writes out of bounds (AddressSanitizer) or has undefined behaviour
//   (UndefinedBehaviorSanitizer), whatever the header claims;
// - what it accepts holds reference/timevarying/FORMAT.md's "invariants a decoder may rely on": every voxel of every
//   time step decodes (ref::decodeStep) without an exception, through texels inside the
//   textures; a std::out_of_range from the decoder is a contract violation and escapes;
// - writing back what was read gives the same bytes (serializeTimeVarying), but for the CRC-32
//   trailer, which fuzz builds do not check (reference/common/crc32.h).
// Size cap: the textures' sizes are bounded by the input's length (the parser checks them
// against it), the decoded volume is not: a file of 100 kB can describe 512^3 voxels per step.
// Decoding is skipped above 2^18 voxels in all (time steps x original extents) to keep each run
// in the millisecond range; parsing is never skipped.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "reference/common/byte_stream.h"
#include "reference/timevarying/container.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voxref;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  ref::TimeVaryingFile f;
  try {
    f = ref::parseTimeVarying(bytes);
  } catch (const ref::StreamError&) {
    return 0;
  }
  const std::string again = ref::serializeTimeVarying(f);
  if (again.size() != size || std::string_view(again).substr(0, size - 4) != bytes.substr(0, size - 4)) {
    std::fprintf(stderr, "serializeTimeVarying(parseTimeVarying(b)) != b (%zu bytes, %zu written back)\n", size,
                 again.size());
    std::abort();
  }
  const ref::TimeVaryingLayout& L = f.textures.layout;
  const std::uint64_t voxels = static_cast<std::uint64_t>(L.timeSteps) * L.original[0] * L.original[1] * L.original[2];
  if (voxels > (std::uint64_t{1} << 18)) return 0;
  for (int t = 0; t < L.timeSteps; ++t) (void)ref::decodeStep(f.textures, t);  // std::out_of_range escapes: a finding
  return 0;
}
