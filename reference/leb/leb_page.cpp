#include "reference/leb/leb_page.h"

#include <algorithm>
#include <string>

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"

namespace voxref::ref {
namespace {

std::string pageName(const LebChannel& c, std::uint64_t page) {
  return std::string(c.kind == LebChannelKind::Data ? "data" : "gradients") + " page " + std::to_string(page);
}

}  // namespace

std::uint64_t insidePointsOfPage(const HzOrder& order, const Dims3& dims, int pageBits, std::uint64_t page) {
  const std::uint64_t begin = page << pageBits, end = std::min(order.size(), (page + 1) << pageBits);
  std::uint64_t n = 0;
  for (HzCursor c(order, begin); c.index() < end; c.next()) n += insideVolume(c.point(), dims);
  return n;
}

Lead1PageReader openPage(const LebStream& s, const LebChannel& c, std::uint64_t page) {
  const std::string_view bytes = s.page(c, page);
  const std::size_t offset = c.payloadOffset + static_cast<std::size_t>(c.pageOffset[page]);
  if (!crc32Matches(bytes, c.pageCrc[page]))
    throw StreamError(offset, pageName(c, page) + ": CRC-32 mismatch (the page is corrupt)");
  return Lead1PageReader(*c.decoder, bytes, offset, pageName(c, page));
}

std::vector<std::int16_t> decodePagePositions(const LebStream& s, const LebChannel& c, const HzOrder& order,
                                              std::uint64_t page) {
  Lead1PageReader reader = openPage(s, c, page);
  const std::size_t comps = static_cast<std::size_t>(c.components);
  std::vector<std::int16_t> out((std::size_t{1} << s.pageBits) * comps, 0);
  const std::uint64_t begin = page << s.pageBits, end = std::min(order.size(), (page + 1) << s.pageBits);
  for (HzCursor cur(order, begin); cur.index() < end; cur.next())
    if (insideVolume(cur.point(), s.dims))
      for (std::size_t k = 0; k < comps; ++k)
        out[static_cast<std::size_t>(cur.index() - begin) * comps + k] = static_cast<std::int16_t>(reader.next());
  reader.finish();
  return out;
}

}  // namespace voxref::ref
