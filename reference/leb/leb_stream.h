// The byte stream of the LEB codec: FORMAT.md beside this file is its definition, and
// parseLebStream follows it section by section.
//
// parseLebStream is safe on untrusted bytes: it checks every field, the header and descriptor
// CRC-32s, the code tables of a lead-1 stream (prefix-free, lengths within the limit) and that the
// page table fits the stream, before it keeps anything; the page payloads are checked (CRC-32,
// then the lead-1 or the adaptive page decoder) when a page is decoded. Errors are StreamError (byte_stream.h) naming
// the offset and the field. Memory: the parsed stream keeps the bytes, plus 16 bytes per stored page and channel (the
// page table, whose 12 bytes per stored page are checked to lie in the stream before it is allocated: at most 1.4 times
// the stream's size) and the code's decoding tables (a few KiB). Claimed sizes (total_bytes, payload_bytes, a page
// table of 2^40 bytes) are checked against the stream's length before anything is allocated for them; what decoding the
// volume costs is lebDecodeMemoryBytes (leb_codec.h).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "reference/common/volume.h"
#include "reference/leb/lead1_coder.h"
#include "reference/leb/leb_grid.h"

namespace voxref::ref {

enum class LebChannelKind : std::uint8_t { Data = 0, Gradients = 1 };

// The entropy stage of a stream's pages (FORMAT.md, header byte 22): the paper's lead-1 Huffman
// code (lead1_coder.h; version 2 streams) or voxref's adaptive range coder
// (adaptive_delta_coder.h; version 3), which code the same deltas; or voxref's context coder of
// the samples and the gradients (context_value_coder.h, context_gradient_coder.h; version 4), whose
// pages decode with their corners' values.
enum class LebCoder : std::uint8_t { Lead1 = 0, Adaptive = 1, Context = 2 };
std::string_view lebCoderName(LebCoder coder);  // "lead1", "adaptive", "context"

struct LebChannel {
  LebChannelKind kind = LebChannelKind::Data;
  int components = 1;  // 1 for data, 3 for gradients (gx, gy, gz interleaved per point)
  int valueBits = 8;   // data: the sample bits; gradients: 8
  bool isSigned = false;
  Lead1Code code;                               // lead-1 streams only
  std::shared_ptr<const Lead1Decoder> decoder;  // built from `code` by parseLebStream; null for adaptive
  std::size_t descriptorOffset = 0, descriptorBytes = 0;
  std::size_t payloadOffset = 0;  // of the first page, in the stream
  // The stored pages (those holding a point of the volume; FORMAT.md, version 2), ascending: the
  // j-th stored page is page storedPage[j], its bytes [pageOffset[j], pageOffset[j + 1]) after
  // payloadOffset, its CRC-32 pageCrc[j].
  std::vector<std::uint32_t> storedPage;
  std::vector<std::uint64_t> pageOffset;
  std::vector<std::uint32_t> pageCrc;
  std::uint64_t payloadBytes() const { return pageOffset.empty() ? 0 : pageOffset.back(); }
  // The slot j of page `page` among the stored pages, or -1 when the stream does not store it.
  std::ptrdiff_t slotOf(std::uint64_t page) const;
};

struct LebStream {
  // The whole stream: `owner` keeps its bytes alive (a string that parseLebStream took, or a file
  // mapping of the caller's), `bytes` views them.
  std::string_view bytes;
  std::shared_ptr<const void> owner;
  Dims3 dims{0, 0, 0};  // the original volume; the grid covers it (padding beyond)
  int sampleBits = 8;
  LebGrid grid;
  int pageBits = 12;  // a page holds 2^pageBits consecutive hierarchical indices
  LebCoder coder = LebCoder::Lead1;
  // FORMAT.md, header byte 23: the stream stores no gradients channel, and its gradients are those
  // quantizedGradients (gradients.h) gives of its decoded samples.
  bool derivedGradients = false;
  std::vector<LebChannel> channels;

  std::uint64_t pageCount() const;  // all pages of the grid, stored or not
  // The bytes of stored page slot j (LebChannel::slotOf).
  std::string_view page(const LebChannel& c, std::size_t slot) const;
  const LebChannel* channel(LebChannelKind kind) const;
  // Whether a decoder gives gradients: a gradients channel, or gradients derived from the data.
  bool hasGradients() const { return derivedGradients || channel(LebChannelKind::Gradients) != nullptr; }
};

inline constexpr std::size_t kLebHeaderBytes = 36;
inline constexpr int kLebVersion = 2;          // lead-1 streams
inline constexpr int kLebAdaptiveVersion = 3;  // streams of the adaptive coder
inline constexpr int kLebContextVersion = 4;   // streams of the context coder
inline int lebVersionOf(LebCoder coder) {
  return coder == LebCoder::Lead1      ? kLebVersion
         : coder == LebCoder::Adaptive ? kLebAdaptiveVersion
                                       : kLebContextVersion;
}
inline constexpr int kMinLebPageBits = 4, kMaxLebPageBits = 20;
// The pages of a grid in pages of 2^pageBits indices, stored or not: ceil((2^k + 1)^3 / 2^pageBits).
inline std::uint64_t lebPageCount(const LebGrid& grid, int pageBits) {
  return (grid.pointCount() + (std::uint64_t{1} << pageBits) - 1) >> pageBits;
}

// One channel's descriptor as the encoder fills it (FORMAT.md, "Descriptor"): what it is, its code,
// and per stored page (ascending: the pages that hold a point of the volume) its length and CRC-32.
struct LebChannelTable {
  LebChannelKind kind = LebChannelKind::Data;
  int components = 1, valueBits = 8;
  bool isSigned = false;
  Lead1Code code;  // written for lead-1 only
  std::vector<std::uint32_t> storedPage, pageLength, pageCrc;
  LebCoder coder = LebCoder::Lead1;
  std::uint64_t payloadBytes() const;
};
// The header (section 1) of a stream of `totalBytes` bytes with `channelCount` channels, its
// version the coder's (lebVersionOf); `derivedGradients` sets byte 23 (then channelCount is 1).
std::string lebHeaderBytes(const Dims3& dims, int sampleBits, const LebGrid& grid, int pageBits, int channelCount,
                           std::uint64_t totalBytes, LebCoder coder = LebCoder::Lead1, bool derivedGradients = false);
// The descriptor of a channel (section 2) among `pageCount` pages, with its CRC-32; exactly
// lebDescriptorSize(valueBits, storedPage.size(), coder) bytes (the code lengths only for lead-1).
// Throws std::invalid_argument for a table whose stored pages are not ascending below pageCount,
// or whose columns differ in length.
std::string lebDescriptorBytes(std::uint64_t pageCount, const LebChannelTable& table);
inline std::size_t lebCodeTableSize(int valueBits, LebCoder coder) {
  const auto symbols = static_cast<std::size_t>(valueBits + 1);
  return coder == LebCoder::Lead1 ? symbols * symbols : 0;
}
inline std::size_t lebDescriptorSize(int valueBits, std::size_t storedPages, LebCoder coder = LebCoder::Lead1) {
  return 20 + lebCodeTableSize(valueBits, coder) + 12 * storedPages + 4;
}

// Throws StreamError. Takes the bytes by value: the stream keeps them.
LebStream parseLebStream(std::string bytes);
// The same over bytes that `owner` keeps alive (a file mapping): nothing is copied.
LebStream parseLebStream(std::string_view bytes, std::shared_ptr<const void> owner);

}  // namespace voxref::ref
