// libFuzzer target: the pages of voxref's adaptive delta coder (reference/leb/adaptive_delta_coder.h,
// range_coder.h; reference/leb/FORMAT.md, "Adaptive pages"). A page is untrusted bytes, and its decoder is
// told how many values the page holds (a stream knows it from the extents), since a value may
// cost less than a bit and decoding does not stop by itself.
//
// Input: byte 0 selects the shape (bit 0: 16-bit values, else 8; bit 1: 3 components, else 1),
// bytes 1-2 the number of values n (little endian, taken modulo 4097), the rest is the page.
// Contract under test:
// - AdaptivePageReader's constructor, next() and finish() either succeed or throw StreamError;
//   nothing else escapes, nothing reads out of bounds (ASan) or has undefined behaviour (UBSan);
// - every value decoded lies in the b-bit two's complement range [-2^(b-1), 2^(b-1));
// - a page that decodes completely (n values, then finish() accepts it) holds values that
//   encodeAdaptivePage codes into a page that decodes to the same values (the bytes may differ:
//   the last bytes of a range-coded page are not unique).
// Size cap: at most 4096 values per input, as a page of 2^12 points.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "reference/common/byte_stream.h"
#include "reference/leb/adaptive_delta_coder.h"

namespace {

using namespace voxref::ref;

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "contract violated: %s\n", what);
  std::abort();
}

// The values of a page read whole, or false when the reader refuses it somewhere.
bool decodeWhole(std::string_view page, int bits, int components, std::vector<std::int32_t>& values) {
  try {
    AdaptivePageReader reader(page, bits, components, 100, "fuzz page");
    for (std::int32_t& v : values) {
      v = reader.next();
      if (v < -(1 << (bits - 1)) || v >= (1 << (bits - 1))) violated("a value outside the b-bit range");
    }
    if (reader.valuesRead() != values.size()) violated("valuesRead() disagrees with the values read");
    reader.finish();
    return true;
  } catch (const StreamError&) {
    return false;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  const int bits = (data[0] & 1) ? 16 : 8, components = (data[0] & 2) ? 3 : 1;
  const std::size_t n = (static_cast<std::size_t>(data[1]) | (static_cast<std::size_t>(data[2]) << 8)) % 4097;
  const std::string page(reinterpret_cast<const char*>(data) + 3, size - 3);
  std::vector<std::int32_t> values(n);
  if (!decodeWhole(page, bits, components, values)) return 0;
  const std::string again = encodeAdaptivePage(values, bits, components);  // std::invalid_argument would be a finding
  std::vector<std::int32_t> back(n);
  if (!decodeWhole(again, bits, components, back) || back != values)
    violated("encodeAdaptivePage of a page's values does not decode to them");
  return 0;
}
