// libFuzzer target: the pages of voxref's context coder, of samples and of gradients
// (reference/leb/context_value_coder.h, context_gradient_coder.h; reference/leb/FORMAT.md, "Context
// pages", "Context gradient pages"). A page is untrusted bytes; its points' corners outside it come
// from a known volume, as a decoder has them from the pages before.
//
// Input: six bytes that pick the channel, the sample bits, the extents, the page bits and one of
// the volume's stored pages (context_page_input.h, shared with the seed maker), then the page's bytes.
// Contract under test:
// - the readers' constructors and decode() either succeed or throw StreamError; nothing else
//   escapes, nothing reads out of bounds (ASan) or has undefined behaviour (UBSan);
// - every value decoded lies in [0, 2^b);
// - a page that decodes completely holds values (vectors) that encodeContextPage
//   (encodeContextGradientPage) codes into a page that decodes to the same values (the bytes may differ: the last bytes
//   of a range-coded page are not unique).
// Size cap: 12^3 samples, pages of at most 2^6 points.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "reference/common/byte_stream.h"
#include "reference/leb/context_gradient_coder.h"
#include "reference/leb/context_value_coder.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/leb_padding.h"
#include "tests/fuzz/context_page_input.h"

namespace {

using namespace voxref::ref;

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "contract violated: %s\n", what);
  std::abort();
}

// Decodes `page` into `values`, or false when the reader refuses it.
bool decodePage(const std::string& page, const HzOrder& order, const voxref::fuzz::ContextPageInput& in,
                std::vector<std::int32_t>& values) {
  try {
    voxref::fuzz::decodeInputPage(page, order, in, values);
  } catch (const StreamError&) {
    return false;
  }
  for (const std::int32_t v : values)
    if (v < 0 || v >= (1 << in.bits)) violated("a value outside [0, 2^b)");
  return true;
}

// The same for a page of gradients (any int8 triple is a valid vector).
bool decodeGradientPage(const std::string& page, const HzOrder& order, const voxref::fuzz::ContextPageInput& in,
                        std::vector<std::array<std::int8_t, 3>>& vectors) {
  try {
    voxref::fuzz::decodeInputGradientPage(page, order, in, vectors);
  } catch (const StreamError&) {
    return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < voxref::fuzz::kContextPageHeader) return 0;
  const HzOrder order(voxref::fuzz::contextPageGrid(data));
  const voxref::fuzz::ContextPageInput in = voxref::fuzz::contextPageInput(order, data);
  const std::string page(reinterpret_cast<const char*>(data) + voxref::fuzz::kContextPageHeader,
                         size - voxref::fuzz::kContextPageHeader);
  if (in.gradients) {
    std::vector<std::array<std::int8_t, 3>> vectors = in.vectors;
    if (!decodeGradientPage(page, order, in, vectors)) return 0;
    const std::string again = encodeContextGradientPage(
        order, in.dims, in.pageBits, in.page, [&](const GridPoint& q) { return vectors[volumeIndex(q, in.dims)]; });
    std::vector<std::array<std::int8_t, 3>> back = in.vectors;
    if (!decodeGradientPage(again, order, in, back) || back != vectors)
      violated("encodeContextGradientPage of a page's vectors does not decode to them");
    return 0;
  }
  std::vector<std::int32_t> values = in.volume;
  if (!decodePage(page, order, in, values)) return 0;
  const std::string again = encodeContextPage(order, in.dims, in.bits, in.pageBits, in.page,
                                              [&](const GridPoint& q) { return values[volumeIndex(q, in.dims)]; });
  std::vector<std::int32_t> back = in.volume;
  if (!decodePage(again, order, in, back) || back != values)
    violated("encodeContextPage of a page's values does not decode to them");
  return 0;
}
