// libFuzzer target: the LEB stream parser, the whole-volume decoder and the random-access reader
// on arbitrary bytes. Contract under test (reference/leb/leb_stream.h, leb_codec.h): any input
// either decodes or throws StreamError; nothing else escapes, and nothing reads or writes out of
// bounds (AddressSanitizer) or overflows (UndefinedBehaviorSanitizer).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include "reference/common/byte_stream.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voxref::ref;
  std::shared_ptr<const LebStream> s;
  try {
    s = std::make_shared<const LebStream>(parseLebStream(std::string(reinterpret_cast<const char*>(data), size)));
  } catch (const StreamError&) {
    return 0;
  }
  // Decoding time and memory grow with the grid (the stream's length bounds only the volume):
  // keep each run short by decoding grids of up to 129^3 points.
  if (s->grid.pointCount() > std::uint64_t{129} * 129 * 129) return 0;
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
