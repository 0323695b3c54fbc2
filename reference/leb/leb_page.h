// Pages of an LEB stream: the unit of decoding and of random access (Gregorski et al. 2004,
// section 3.1: "the transformed coefficients are divided into pages and each page is encoded
// separately"). Page i holds the hierarchical indices [i 2^p, (i + 1) 2^p); only the points
// inside the volume are coded in it.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "reference/common/byte_stream.h"
#include "reference/leb/adaptive_delta_coder.h"
#include "reference/leb/decoded_page.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/leb_padding.h"
#include "reference/leb/leb_stream.h"

namespace voxref::ref {

// How many of the page's points lie inside the volume (a walk over the page's indices).
std::uint64_t insidePointsOfPage(const HzOrder& order, const Dims3& dims, int pageBits, std::uint64_t page);

// The error of a page that holds points of the volume but is not in the stream's page table.
StreamError pageNotStored(const LebChannel& c, std::uint64_t page);
// The error of a page in the stream's page table that holds no point of the volume.
StreamError pageWithoutPoints(const LebChannel& c, std::uint64_t page);

// The deltas of one page, by the stream's coder (LebStream::coder): the same values and errors
// whichever coder made the page.
class LebPageReader {
 public:
  explicit LebPageReader(Lead1PageReader r) : r_(std::move(r)) {}
  explicit LebPageReader(AdaptivePageReader r) : r_(std::move(r)) {}
  std::int32_t next() {
    return std::visit([](auto& r) { return r.next(); }, r_);
  }
  void read(std::span<std::int32_t> out) {
    std::visit([&](auto& r) { r.read(out); }, r_);
  }
  // a.read(outA), then b.read(outB): the same values and errors; two lead-1 pages are read
  // interleaved (Lead1PageReader::readBoth).
  static void readBoth(LebPageReader& a, std::span<std::int32_t> outA, LebPageReader& b, std::span<std::int32_t> outB) {
    Lead1PageReader* la = std::get_if<Lead1PageReader>(&a.r_);
    Lead1PageReader* lb = std::get_if<Lead1PageReader>(&b.r_);
    if (la && lb) return Lead1PageReader::readBoth(*la, outA, *lb, outB);
    a.read(outA);
    b.read(outB);
  }
  void finish() const {
    std::visit([](const auto& r) { r.finish(); }, r_);
  }
  std::size_t valuesRead() const {
    return std::visit([](const auto& r) { return r.valuesRead(); }, r_);
  }

 private:
  std::variant<Lead1PageReader, AdaptivePageReader> r_;
};

// A stored page's bytes, the offset of its first byte in the stream and its name ("data page 17"),
// its CRC-32 checked: StreamError naming the channel, the page and its offset, or pageNotStored for
// a page the table lacks. The bytes are the stream's.
struct StoredPage {
  std::string_view bytes;
  std::size_t offset = 0;
  std::string name;
};
StoredPage storedPage(const LebStream& s, const LebChannel& c, std::uint64_t page);

// Checks the page's CRC-32 (storedPage) and returns a reader of its deltas (lead-1 and adaptive
// streams; std::invalid_argument for the context coder's, whose pages hold values); the page
// holds one delta per component of each point inside the volume. The page's bytes are the
// stream's: the stream must outlive the reader.
LebPageReader openPage(const LebStream& s, const LebChannel& c, std::uint64_t page);

// The end of a page read whole: StreamError unless the page held `points` > 0 points of the
// volume (a stream stores no page without one) and nothing is left after its last value (for
// lead-1, nothing but the last byte's zero bits).
void finishPage(const LebPageReader& reader, std::uint64_t points, const LebChannel& c, std::uint64_t page);

// The page's deltas placed at their positions, as LebReader's cache keeps them (DecodedPage::deltas
// of the channel's width): 2^pageBits x components entries, 0 for the padding and for indices past
// the grid's last point. Throws StreamError for a corrupt page.
DecodedPage decodePagePositions(const LebStream& s, const LebChannel& c, const HzOrder& order, std::uint64_t page);

// decodePagePositions of the data page and the gradients page of the same index, {data,
// gradients}, their lead-1 codes read interleaved (LebPageReader::readBoth: the two chains of
// lookups run side by side): what random access asks for when a point needs both channels and
// neither page is cached. The same values and errors as the two calls (the data page's first).
// Throws std::invalid_argument for a stream without both channels stored.
std::array<DecodedPage, 2> decodeChannelPagesPositions(const LebStream& s, const HzOrder& order, std::uint64_t page);

}  // namespace voxref::ref
