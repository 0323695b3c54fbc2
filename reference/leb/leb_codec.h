// Lossless hierarchical compression on the LEB mesh (Gregorski et al. 2004, section 3): the
// encoder, the whole-volume decoder and the stream statistics. Random access is leb_reader.h.
//
// Encoding: a volume of X x Y x Z samples (8 or 16 bits) lies in the smallest (2^k + 1)^3 grid
// that covers it, origin at sample (0, 0, 0). Walking the points inside the volume in
// hierarchical z-order (hz_order.h), every point is predicted from its split edge (prediction.h)
// and its delta is coded; points of the padding are not coded (they take their prediction, and
// only the shell that predictions reach is computed: leb_padding.h). Deltas are cut into pages of
// 2^pageBits indices, each coded on its own with the lead-1 code built from the counts of all
// pages (lead1_coder.h), or with the adaptive coder (options.coder; adaptive_delta_coder.h); only
// pages that hold a point of the volume are stored. The gradients channel
// (gradients.h) is predicted and coded the same way, its three components interleaved per point,
// with a code of its own (so Table 1 can report data and gradients separately), unless the stream
// derives its gradients (options.deriveGradients; FORMAT.md, header byte 23): then it has the data
// channel alone, and a decoder computes quantizedGradients of the samples it decodes.
//
// Exactness: lossless; decodeLeb(parseLebStream(encodeLeb(v))) == v, bit for bit, and the
// gradients equal quantizedGradients(v). Deterministic for any thread count.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "reference/common/volume.h"
#include "reference/leb/leb_stream.h"

namespace voxref::ref {

// Called between batches of pages, on the calling thread, while no worker runs, with the fraction
// of the work done so far (0..1, rising): a caller whose volume lies in file mappings trims them
// there (conformance/io/leb_file_codec.h), which bounds its resident memory by what one batch
// touches, and may show progress. The batches do not change any result.
using LebWindow = std::function<void(double done)>;

struct LebEncodeOptions {
  int pageBits = 12;      // the paper's k = 12: 4096 points per page
  bool gradients = true;  // add the gradients channel
  int threads = 0;        // 0: all cores
  LebWindow window;       // optional
  // The pages' entropy stage: the paper's lead-1 Huffman code (a version 2 stream), or voxref's
  // adaptive range coder (version 3; adaptive_delta_coder.h): the same deltas, the same pages.
  LebCoder coder = LebCoder::Lead1;
  // With `gradients`: store no gradients channel, and mark the stream as deriving them from its
  // samples (voxref's own gradients are a function of the samples, gradients.h, so a decoder
  // computes the same bytes). The span's gradients, if given, are not read: gradients of the
  // caller's own (diffused ones) cannot be derived and need the channel.
  bool deriveGradients = false;
};
// Whether the stream of these options has a gradients channel.
inline bool lebStoresGradients(const LebEncodeOptions& o) { return o.gradients && !o.deriveGradients; }

// A volume where the codec reads it (encoding) or writes it (decoding), x fastest: the samples at 8
// bits (data8) or at 16 (data16), exactly one of them, and the gradients, 3 int8 per sample
// (quantizedGradients), when the stream has them (a channel, or derived).
template <class Byte, class Word, class Signed>
struct LebVolumeSpan {
  Dims3 dims{0, 0, 0};
  int sampleBits = 8;
  Byte* data8 = nullptr;
  Word* data16 = nullptr;
  Signed* gradients = nullptr;
};
using LebVolumeIn = LebVolumeSpan<const std::uint8_t, const std::uint16_t, const std::int8_t>;
using LebVolumeOut = LebVolumeSpan<std::uint8_t, std::uint16_t, std::int8_t>;
// Calls f with the span's samples: its 8-bit array if set, else its 16-bit one.
template <class Span, class F>
void withLebSamples(const Span& v, F&& f) {
  if (v.data8)
    f(v.data8);
  else
    f(v.data16);
}

// Receives the stream being made: its `bytes` at `offset`. Each byte is written once; the
// payload in order, each channel's descriptor after its pages, the header last.
using LebStreamWrite = std::function<void(std::uint64_t offset, std::string_view bytes)>;

// Throws std::invalid_argument for sampleBits other than 8 or 16, a sample >= 2^sampleBits, page
// bits outside [kMinLebPageBits, kMaxLebPageBits], a volume larger than the largest grid, or
// deriveGradients without gradients.
//
// Memory: at most lebEncodeMemoryBytes(dims, options) beside the volume itself: the gradients (3
// bytes per sample), the stream, and what encodeLebTo needs (below: the shell of padding that
// predictions reach, leb_padding.h, and one batch of runs in flight; the encoder makes two passes,
// the counts for the code, then the deltas again, each page coded as it is predicted). Nothing is
// proportional to the grid: pages of padding alone are neither walked nor stored, so a 1025x1x1
// volume costs what its samples cost (FORMAT.md, "Stored pages").
std::string encodeLeb(const Volume<std::uint16_t>& volume, int sampleBits, const LebEncodeOptions& options = {});
// The same stream, handed to `write` as it is made (encodeLeb is this with a string for the
// stream): the streaming encoder of files. Returns the stream's size. Throws as encodeLeb does, and
// std::invalid_argument when the span lacks the samples or, with options.gradients and not
// options.deriveGradients, the gradients.
// Memory beside the span: the shell of padding, one batch of runs of 64 pages of deltas and of
// coded pages per thread, and the page table (12 bytes per stored page); nothing proportional to
// the volume.
std::uint64_t encodeLebTo(const LebVolumeIn& volume, const LebEncodeOptions& options, const LebStreamWrite& write);
// encodeLebTo into a string: the stream of the samples and gradients the span gives (gradients of
// the caller's own, for example diffused ones, gradients.h). Throws as encodeLebTo.
std::string encodeLeb(const LebVolumeIn& volume, const LebEncodeOptions& options = {});
// The memory above, from the extents alone (nothing is allocated).
std::uint64_t lebEncodeToMemoryBytes(const Dims3& dims, const LebEncodeOptions& options = {});
// The bound above, from the extents alone (nothing is allocated). Throws std::invalid_argument as
// encodeLeb does for extents larger than the largest grid.
std::uint64_t lebEncodeMemoryBytes(const Dims3& dims, const LebEncodeOptions& options = {});

struct LebDecoded {
  Volume<std::uint16_t> data;
  std::vector<std::int8_t> gradients;  // 3 per sample; empty when the stream has no gradients
};
// Decodes every page (checking its CRC-32 and its code) and reconstructs the volume; a stream that
// derives its gradients has them computed from the decoded samples (quantizedGradients), in
// parallel by slices. Throws StreamError naming the page and offset of the first corrupt page.
// Memory: at most lebDecodeMemoryBytes(stream), plus one small reader per open page: the volume
// (2 bytes per sample) and its gradients (3 bytes per sample), plus the shells of padding that
// predictions reach, one a channel, held together (leb_padding.h; none for a volume that fills its
// grid): a stream's data and gradients are reconstructed in one walk. A stream of the context
// coder (version 4) holds no shell, and each worker one page's table of 2^pageBits bytes instead of
// the open readers (context_codec.h).
// Nothing is proportional to the grid: a 513x1x1 stream decodes in a few kilobytes. A caller that
// decodes untrusted streams compares lebDecodeMemoryBytes with what it may allocate first (voxref
// decode does). parseLebStream has already refused streams too short for their volume.
LebDecoded decodeLeb(const LebStream& stream, int threads = 0);
// The bound above, from the header alone (nothing is allocated).
std::uint64_t lebDecodeMemoryBytes(const LebStream& stream);
// Its part that the shells of padding take (decodeLebInto holds them whatever its outputs are).
std::uint64_t lebDecodeShellBytes(const LebStream& stream);
// Decodes into `out` (decodeLeb is this with a volume of its own): out.dims and sampleBits must be
// the stream's, data8 set for 8-bit samples and data16 for 16, gradients set exactly when the
// stream has a gradients channel, or when it derives them and they are wanted
// (std::invalid_argument otherwise). window, if set, is called between batches (of pages, then of slices of derived
// gradients, which read the samples of their slice and the two beside it). Memory beside `out`: the shell of padding,
// one channel at a time, and one small reader per open page.
void decodeLebInto(const LebStream& stream, const LebVolumeOut& out, int threads = 0, const LebWindow& window = {});

// The deltas the encoder codes for one channel, in stream order (points inside the volume only):
// what the benchmarks hand to a general-purpose coder to separate the predictor from the coder.
std::vector<std::int32_t> lebDeltas(const Volume<std::uint16_t>& volume, int sampleBits, LebChannelKind kind);

struct LebChannelStats {
  LebChannelKind kind = LebChannelKind::Data;
  std::uint64_t rawBytes = 0;         // the channel's values at 1 or 2 bytes each, volume samples only
  std::uint64_t descriptorBytes = 0;  // code table, page table, CRCs
  std::uint64_t payloadBytes = 0;
  std::uint64_t codedValues = 0;
  std::uint64_t compressedBytes() const { return descriptorBytes + payloadBytes; }
};
struct LebStats {
  Dims3 dims{0, 0, 0};
  int sampleBits = 8, k = 0, pageBits = 0;
  std::uint64_t gridPoints = 0, volumePoints = 0;                              // padding = gridPoints - volumePoints
  std::uint64_t pages = 0, storedPages = 0, headerBytes = 0, streamBytes = 0;  // the grid's pages; those stored
  std::vector<LebChannelStats> channels;
  // Raw bytes over stream bytes; the header is counted with the data channel. The padding is
  // not in the raw bytes (it costs no payload; its page table entries are counted).
  double ratio() const;
  double channelRatio(LebChannelKind kind) const;
};
LebStats lebStats(const LebStream& stream);

}  // namespace voxref::ref
