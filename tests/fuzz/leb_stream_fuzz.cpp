// libFuzzer target: the LEB stream parser, the whole-volume decoder and the random-access reader
// on arbitrary bytes, and the same of mirrored streams (an input that begins with their magic).
// Contract under test (reference/leb/leb_stream.h, leb_codec.h, mirror_stream.h): any input
// either decodes or throws StreamError; nothing else escapes, and nothing reads or writes out of
// bounds (AddressSanitizer) or overflows (UndefinedBehaviorSanitizer).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "reference/common/byte_stream.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_reader.h"
#include "reference/leb/mirror_reader.h"

namespace {

// Keeps each run short: decoding time and memory grow with the grid (the stream's length bounds
// only the volume), so grids of up to 129^3 points are decoded.
bool smallEnough(const voxref::ref::LebStream& s) { return s.grid.pointCount() <= std::uint64_t{129} * 129 * 129; }

int mirrored(const std::string& bytes) {
  using namespace voxref::ref;
  std::shared_ptr<const MirroredLebStream> s;
  try {
    s = std::make_shared<const MirroredLebStream>(parseMirroredLebStream(bytes));
  } catch (const StreamError&) {
    return 0;
  }
  if (!smallEnough(s->inner) || sampleCount(s->header.dims) > std::uint64_t{129} * 129 * 129) return 0;
  try {
    (void)decodeMirroredLeb(*s, 1);
  } catch (const StreamError&) {
  }
  MirroredLebReader reader(s, 1 << 16);
  const Dims3& d = s->header.dims;
  for (const GridPoint& p :
       {GridPoint{0, 0, 0}, GridPoint{d[0] / 2, d[1] / 2, d[2] / 2}, GridPoint{d[0] - 1, d[1] - 1, d[2] - 1}}) {
    try {
      (void)reader.sample(p);
      if (s->header.hasGradients()) (void)reader.gradient(p);
    } catch (const StreamError&) {
    }
  }
  return 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voxref::ref;
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  if (isMirroredLebStream(bytes)) return mirrored(bytes);
  std::shared_ptr<const LebStream> s;
  try {
    s = std::make_shared<const LebStream>(parseLebStream(bytes));
  } catch (const StreamError&) {
    return 0;
  }
  if (!smallEnough(*s)) return 0;
  try {
    (void)decodeLeb(*s, 1);
  } catch (const StreamError&) {
  }
  LebReader reader(s, 1 << 16);
  const int n = s->grid.side();
  for (const GridPoint& p : {GridPoint{0, 0, 0}, GridPoint{n / 2, n / 2, n / 2},
                             GridPoint{s->dims[0] - 1, s->dims[1] - 1, s->dims[2] - 1}}) {
    try {
      (void)reader.sample(p);
      if (s->hasGradients()) (void)reader.gradient(p);  // a channel, or derived from the samples
    } catch (const StreamError&) {
    }
  }
  return 0;
}
