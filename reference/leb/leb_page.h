// Pages of an LEB stream: the unit of decoding and of random access (Gregorski et al. 2004,
// section 3.1: "the transformed coefficients are divided into pages and each page is encoded
// separately"). Page i holds the hierarchical indices [i 2^p, (i + 1) 2^p); only the points
// inside the volume are coded in it.
#pragma once

#include <cstdint>
#include <vector>

#include "reference/common/byte_stream.h"
#include "reference/leb/hz_order.h"
#include "reference/leb/leb_padding.h"
#include "reference/leb/leb_stream.h"

namespace voxref::ref {

// How many of the page's points lie inside the volume (a walk over the page's indices).
std::uint64_t insidePointsOfPage(const HzOrder& order, const Dims3& dims, int pageBits, std::uint64_t page);

// The error of a page that holds points of the volume but is not in the stream's page table.
StreamError pageNotStored(const LebChannel& c, std::uint64_t page);

// Checks the page's CRC-32 (StreamError naming the channel, the page and its offset) and returns
// a reader of its deltas; the page holds one delta per component of each point inside the volume.
Lead1PageReader openPage(const LebStream& s, const LebChannel& c, std::uint64_t page);

// The end of a page read whole: StreamError unless the page held `points` > 0 points of the
// volume (a stream stores no page without one) and nothing but the last byte's zero bits is left.
void finishPage(const Lead1PageReader& reader, std::uint64_t points, const LebChannel& c, std::uint64_t page);

// The page's deltas (each fits an int16) placed at their positions: 2^pageBits x components entries, 0 for the padding
// and for indices past the grid's last point. Throws StreamError for a corrupt page.
std::vector<std::int16_t> decodePagePositions(const LebStream& s, const LebChannel& c, const HzOrder& order,
                                              std::uint64_t page);

}  // namespace voxref::ref
