#include "reference/leb/leb_page.h"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>

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

StoredPage storedPage(const LebStream& s, const LebChannel& c, std::uint64_t page) {
  const std::ptrdiff_t slot = c.slotOf(page);
  if (slot < 0) throw pageNotStored(c, page);
  const auto j = static_cast<std::size_t>(slot);
  StoredPage p{s.page(c, j), c.payloadOffset + static_cast<std::size_t>(c.pageOffset[j]), pageName(c, page)};
  if (!crc32Matches(p.bytes, c.pageCrc[j]))
    throw StreamError(p.offset, p.name + ": CRC-32 mismatch (the page is corrupt)");
  return p;
}

LebPageReader openPage(const LebStream& s, const LebChannel& c, std::uint64_t page) {
  if (s.coder == LebCoder::Context)
    throw std::invalid_argument(
        "openPage: the pages of the context coder hold values, which decode with their "
        "corners' values (ContextPageReader), not deltas");
  StoredPage p = storedPage(s, c, page);
  if (s.coder == LebCoder::Adaptive)
    return LebPageReader(AdaptivePageReader(p.bytes, c.valueBits, c.components, p.offset, std::move(p.name)));
  return LebPageReader(Lead1PageReader(*c.decoder, p.bytes, p.offset, std::move(p.name)));
}

StreamError pageWithoutPoints(const LebChannel& c, std::uint64_t page) {
  return StreamError(c.descriptorOffset, pageName(c, page) +
                                             " is stored, but it holds no point of the volume (a stream stores "
                                             "exactly the pages that do)");
}

void finishPage(const LebPageReader& reader, std::uint64_t points, const LebChannel& c, std::uint64_t page) {
  if (points == 0) throw pageWithoutPoints(c, page);
  reader.finish();
}

namespace {

// Where a page's deltas go: the page's points inside the volume, by their place in the page (`at`
// stays empty for a page wholly inside the volume, most of them, which holds every index of it in
// order).
struct PagePlaces {
  bool all = false;
  std::uint64_t points = 0;
  std::vector<std::uint32_t> at;
};

PagePlaces pagePlaces(const LebStream& s, const HzOrder& order, std::uint64_t page) {
  PagePlaces p;
  const std::uint64_t begin = page << s.pageBits, end = std::min(order.size(), (page + 1) << s.pageBits);
  if (order.allInside(s.dims, begin, end)) {
    p.all = true;
    p.points = end - begin;
    return p;
  }
  p.at.reserve(std::size_t{1} << s.pageBits);
  order.forEachInside(s.dims, begin, end, [&](std::uint64_t h, const GridPoint&, int, int, unsigned) {
    p.at.push_back(static_cast<std::uint32_t>(h - begin));
  });
  p.points = p.at.size();
  return p;
}

// The deltas of a page's points (in the order its reader gives them) at their places, in a page of
// the channel's width (DecodedPage::deltas).
DecodedPage placeDeltas(const PagePlaces& p, std::span<const std::int32_t> deltas, std::size_t comps, int pageBits,
                        int valueBits) {
  DecodedPage out = DecodedPage::deltas((std::size_t{1} << pageBits) * comps, valueBits);
  out.withStorage([&](auto* entries) {
    using Entry = std::remove_pointer_t<decltype(entries)>;
    if (p.all) {
      for (std::size_t i = 0; i < deltas.size(); ++i) entries[i] = static_cast<Entry>(deltas[i]);
      return;
    }
    for (std::size_t i = 0; i < p.at.size(); ++i)
      for (std::size_t k = 0; k < comps; ++k)
        entries[static_cast<std::size_t>(p.at[i]) * comps + k] = static_cast<Entry>(deltas[i * comps + k]);
  });
  return out;
}

}  // namespace

DecodedPage decodePagePositions(const LebStream& s, const LebChannel& c, const HzOrder& order, std::uint64_t page) {
  LebPageReader reader = openPage(s, c, page);
  const PagePlaces places = pagePlaces(s, order, page);
  const std::size_t comps = static_cast<std::size_t>(c.components);
  // The deltas in one run (LebPageReader::read, the order next() would give them), placed after.
  std::vector<std::int32_t> deltas(static_cast<std::size_t>(places.points) * comps);
  if (!deltas.empty()) reader.read(deltas);
  finishPage(reader, places.points, c, page);
  return placeDeltas(places, deltas, comps, s.pageBits, c.valueBits);
}

std::array<DecodedPage, 2> decodeChannelPagesPositions(const LebStream& s, const HzOrder& order, std::uint64_t page) {
  const LebChannel* data = s.channel(LebChannelKind::Data);
  const LebChannel* gradients = s.channel(LebChannelKind::Gradients);
  if (!data || !gradients)
    throw std::invalid_argument("decodeChannelPagesPositions: the stream does not store both channels");
  // Each error as the two calls would report it: anything wrong with the data page comes first.
  LebPageReader a = openPage(s, *data, page);
  const PagePlaces places = pagePlaces(s, order, page);
  const std::size_t ca = static_cast<std::size_t>(data->components),
                    cb = static_cast<std::size_t>(gradients->components);
  std::vector<std::int32_t> da(static_cast<std::size_t>(places.points) * ca),
      db(static_cast<std::size_t>(places.points) * cb);
  std::optional<LebPageReader> b;
  try {
    b.emplace(openPage(s, *gradients, page));
  } catch (const StreamError&) {
    if (!da.empty()) a.read(da);
    finishPage(a, places.points, *data, page);
    throw;
  }
  try {
    if (places.points > 0) LebPageReader::readBoth(a, da, *b, db);
  } catch (const StreamError&) {
    if (a.valuesRead() == da.size()) finishPage(a, places.points, *data, page);  // then b's error
    throw;
  }
  finishPage(a, places.points, *data, page);
  finishPage(*b, places.points, *gradients, page);
  return {placeDeltas(places, da, ca, s.pageBits, data->valueBits),
          placeDeltas(places, db, cb, s.pageBits, gradients->valueBits)};
}

}  // namespace voxref::ref
