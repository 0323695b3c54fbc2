// The whole-volume encoder and decoder of the context coder's streams (version 4; FORMAT.md beside
// this file, "Context pages" and "Context gradient pages"; the values' coding is
// context_value_coder.h, the gradients' context_gradient_coder.h). leb_codec.h's encodeLebTo and
// decodeLebInto call them for LebCoder::Context: a stream of this coder has the data channel and,
// unless it derives them or has none, the gradients channel.
//
// Encoding: every stored page (those holding a point of the volume) is coded from the samples on
// its own, pages in parallel, in batches whose coded pages are written in order before the next.
// Decoding: a page's points need the values of their corners, which are coarser; so the pages go in
// waves, each wave the stored pages whose corners all lie in the waves before it (the pages of one
// scale, nearly all the grid's, are one wave), decoded in parallel straight into the output.
// Deterministic: the same bytes for every thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "reference/leb/hz_order.h"
#include "reference/leb/leb_codec.h"
#include "reference/leb/leb_stream.h"

namespace voxref::ref {

// Told how far the work has come (0..1, rising), between batches, with no worker running (the
// caller's LebWindow, scaled to this part of its work).
using LebProgress = std::function<void(double done)>;
// `whole` told of one part of its work, the part [base, base + span) of it: done (0..1) of the part
// is base + span x done of the whole. Empty when `whole` is.
LebProgress lebProgressPart(const LebProgress& whole, double base, double span);

// The stored pages of a volume: those holding one of its points, ascending (one walk of its
// points: forEachInside skips the padding whole, so a 1025x1x1 volume costs its 1025 points).
std::vector<std::uint32_t> contextStoredPages(const HzOrder& order, const Dims3& dims, int pageBits);

// Writes channel `kind` of `v` (its samples, or its gradients) at `offset` onward (its
// descriptor, then its pages `stored` (contextStoredPages), as FORMAT.md lays them out) through
// `write`, and returns the offset after it.
// Memory beside the span: the stored pages' table (12 bytes a page) and one batch of coded pages
// (4 x workers pages of at most about 2^pageBits x 3 bytes, 9 for the gradients), plus 2^pageBits
// bytes a worker (3 for the gradients, and 8 more with a gradient page's recent vectors, whose
// page is coded twice: encodeContextGradientPage).
std::uint64_t encodeContextChannel(const HzOrder& order, const LebVolumeIn& v, LebChannelKind kind,
                                   const std::vector<std::uint32_t>& stored, int pageBits, int threads,
                                   const LebProgress& progress, const LebStreamWrite& write, std::uint64_t offset);

// The page below which every page must be decoded before `page` can be: the pages that hold the
// corners of its points (all but those in `page` itself, which it decodes before it reads them).
// Conservative: every page below the first level of the scale of the page's last index, or `page`
// when that level begins in it.
std::uint64_t contextPagesNeededBelow(const HzOrder& order, int pageBits, std::uint64_t page);

// Decodes the channels of a version 4 stream: the data into out.data8 or out.data16, then any
// gradients channel into out.gradients. Checks each channel's page table against the extents
// first (StreamError for a page holding points of the volume that the stream lacks), then each page
// as it is decoded (its CRC-32, its values, its end).
// Memory beside `out`: the table of waves (8 bytes a stored page) and 2^pageBits bytes a worker
// (3 for the gradients, and 8 more for a gradient page's recent vectors, recent_vectors.h).
void decodeContextChannels(const LebStream& s, const HzOrder& order, const LebVolumeOut& out, int threads,
                           const LebProgress& progress);

}  // namespace voxref::ref
