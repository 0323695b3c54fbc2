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
  return order.countInside(dims, page << pageBits, (page + 1) << pageBits);
}

StreamError pageNotStored(const LebChannel& c, std::uint64_t page) {
  return StreamError(c.descriptorOffset, pageName(c, page) +
                                             " holds points of the volume, but the stream does not store it (the page "
                                             "table lacks it)");
}

LebPageReader openPage(const LebStream& s, const LebChannel& c, std::uint64_t page) {
  const std::ptrdiff_t slot = c.slotOf(page);
  if (slot < 0) throw pageNotStored(c, page);
  const auto j = static_cast<std::size_t>(slot);
  const std::string_view bytes = s.page(c, j);
  const std::size_t offset = c.payloadOffset + static_cast<std::size_t>(c.pageOffset[j]);
  if (!crc32Matches(bytes, c.pageCrc[j]))
    throw StreamError(offset, pageName(c, page) + ": CRC-32 mismatch (the page is corrupt)");
  if (s.coder == LebCoder::Adaptive)
    return LebPageReader(AdaptivePageReader(bytes, c.valueBits, c.components, offset, pageName(c, page)));
  return LebPageReader(Lead1PageReader(*c.decoder, bytes, offset, pageName(c, page)));
}

void finishPage(const LebPageReader& reader, std::uint64_t points, const LebChannel& c, std::uint64_t page) {
  if (points == 0)
    throw StreamError(c.descriptorOffset, pageName(c, page) +
                                              " is stored, but it holds no point of the volume (a stream stores "
                                              "exactly the pages that do)");
  reader.finish();
}

std::vector<std::int16_t> decodePagePositions(const LebStream& s, const LebChannel& c, const HzOrder& order,
                                              std::uint64_t page) {
  LebPageReader reader = openPage(s, c, page);
  const std::size_t comps = static_cast<std::size_t>(c.components);
  const std::size_t size = std::size_t{1} << s.pageBits;
  std::vector<std::int16_t> out(size * comps, 0);
  const std::uint64_t begin = page << s.pageBits, end = std::min(order.size(), (page + 1) << s.pageBits);
  // A page wholly inside the volume (most of them) holds every index of it, in order.
  if (order.allInside(s.dims, begin, end)) {
    std::vector<std::int32_t> deltas(static_cast<std::size_t>(end - begin) * comps);
    if (!deltas.empty()) reader.read(deltas);
    std::transform(deltas.begin(), deltas.end(), out.begin(),
                   [](std::int32_t d) { return static_cast<std::int16_t>(d); });
    finishPage(reader, end - begin, c, page);
    return out;
  }
  // Otherwise the page's points inside the volume, by their place in the page; then their deltas
  // in one run (LebPageReader::read, the order next() would give them), placed after.
  std::vector<std::uint32_t> at;
  at.reserve(size);
  order.forEachInside(s.dims, begin, end, [&](std::uint64_t h, const GridPoint&, int, int, unsigned) {
    at.push_back(static_cast<std::uint32_t>(h - begin));
  });
  std::vector<std::int32_t> deltas(at.size() * comps);
  if (!at.empty()) reader.read(deltas);
  for (std::size_t i = 0; i < at.size(); ++i)
    for (std::size_t k = 0; k < comps; ++k)
      out[static_cast<std::size_t>(at[i]) * comps + k] = static_cast<std::int16_t>(deltas[i * comps + k]);
  finishPage(reader, at.size(), c, page);
  return out;
}

}  // namespace voxref::ref
