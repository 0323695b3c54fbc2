#include "reference/leb/leb_stream.h"

#include <algorithm>
#include <stdexcept>

#include "reference/common/byte_stream.h"
#include "reference/common/crc32.h"
#include "reference/leb/adaptive_delta_coder.h"

namespace voxref::ref {

std::string_view lebCoderName(LebCoder coder) {
  return coder == LebCoder::Lead1 ? "lead1" : coder == LebCoder::Adaptive ? "adaptive" : "context";
}

std::uint64_t LebStream::pageCount() const { return lebPageCount(grid, pageBits); }

std::ptrdiff_t LebChannel::slotOf(std::uint64_t page) const {
  const auto it = std::lower_bound(storedPage.begin(), storedPage.end(), page);
  return it != storedPage.end() && *it == page ? it - storedPage.begin() : -1;
}

std::string_view LebStream::page(const LebChannel& c, std::size_t slot) const {
  const std::uint64_t begin = c.pageOffset[slot], end = c.pageOffset[slot + 1];
  return bytes.substr(c.payloadOffset + begin, end - begin);
}

const LebChannel* LebStream::channel(LebChannelKind kind) const {
  for (const LebChannel& c : channels)
    if (c.kind == kind) return &c;
  return nullptr;
}

std::uint64_t LebChannelTable::payloadBytes() const {
  std::uint64_t n = 0;
  for (const std::uint32_t len : pageLength) n += len;
  return n;
}

std::string lebHeaderBytes(const Dims3& dims, int sampleBits, const LebGrid& grid, int pageBits, int channelCount,
                           std::uint64_t totalBytes, LebCoder coder, bool derivedGradients) {
  // FORMAT.md section 1.
  ByteWriter w;
  w.bytes("VXLB", 4);
  w.le<std::uint16_t>(static_cast<std::uint16_t>(lebVersionOf(coder)));
  w.le<std::uint8_t>(static_cast<std::uint8_t>(sampleBits));
  w.le<std::uint8_t>(static_cast<std::uint8_t>(grid.k));
  for (int a = 0; a < 3; ++a) w.le<std::uint32_t>(static_cast<std::uint32_t>(dims[a]));
  w.le<std::uint8_t>(static_cast<std::uint8_t>(pageBits));
  w.le<std::uint8_t>(static_cast<std::uint8_t>(channelCount));
  w.le<std::uint8_t>(static_cast<std::uint8_t>(coder));
  w.le<std::uint8_t>(derivedGradients ? 1 : 0);
  w.le<std::uint64_t>(totalBytes);
  w.le<std::uint32_t>(crc32(w.str()));
  return std::move(w.str());
}

std::string lebDescriptorBytes(std::uint64_t pages, const LebChannelTable& c) {
  // FORMAT.md section 2, "Descriptor".
  const std::size_t n = c.storedPage.size();
  if (n == 0 || c.pageLength.size() != n || c.pageCrc.size() != n ||
      !std::is_sorted(c.storedPage.begin(), c.storedPage.end(), std::less_equal<>()) || c.storedPage.back() >= pages)
    throw std::invalid_argument("a channel stores one length and CRC per ascending page index below " +
                                std::to_string(pages));
  ByteWriter w;
  w.le<std::uint8_t>(static_cast<std::uint8_t>(c.kind));
  w.le<std::uint8_t>(static_cast<std::uint8_t>(c.components));
  w.le<std::uint8_t>(static_cast<std::uint8_t>(c.valueBits));
  w.le<std::uint8_t>(c.isSigned ? 1 : 0);
  w.le<std::uint32_t>(static_cast<std::uint32_t>(pages));
  w.le<std::uint32_t>(static_cast<std::uint32_t>(n));
  w.le<std::uint64_t>(c.payloadBytes());
  if (c.coder == LebCoder::Lead1) {
    if (c.code.lengths.size() != lebCodeTableSize(c.valueBits, c.coder))
      throw std::invalid_argument("a lead-1 channel needs its code lengths");
    w.bytes(c.code.lengths.data(), c.code.lengths.size());
  }
  for (const std::uint32_t p : c.storedPage) w.le<std::uint32_t>(p);
  for (const std::uint32_t len : c.pageLength) w.le<std::uint32_t>(len);
  for (const std::uint32_t crc : c.pageCrc) w.le<std::uint32_t>(crc);
  w.le<std::uint32_t>(crc32(w.str()));
  return std::move(w.str());
}

LebStream parseLebStream(std::string bytes) {
  auto owner = std::make_shared<const std::string>(std::move(bytes));
  const std::string_view view = *owner;
  return parseLebStream(view, std::move(owner));
}

LebStream parseLebStream(std::string_view bytes, std::shared_ptr<const void> owner) {
  LebStream s;
  s.bytes = bytes;
  s.owner = std::move(owner);
  const std::string_view b = s.bytes;
  ByteReader r(b);
  // Section 1: header.
  if (r.take(4, "magic") != std::string_view("VXLB", 4)) r.fail(0, "magic: expected 'VXLB' (not an LEB stream)");
  r.need(kLebHeaderBytes - 4, "header");
  if (!crc32Matches(b.substr(0, 32), static_cast<std::uint32_t>(loadLe(b.data() + 32, 4))))
    r.fail(32, "header_crc: CRC-32 mismatch (the header is corrupt)");
  const std::size_t versionAt = r.offset();
  const int version = r.le<std::uint16_t>("version");
  if (version != kLebVersion && version != kLebAdaptiveVersion && version != kLebContextVersion)
    r.fail(versionAt, "version: expected " + std::to_string(kLebVersion) + " (lead-1), " +
                          std::to_string(kLebAdaptiveVersion) + " (adaptive) or " + std::to_string(kLebContextVersion) +
                          " (context), got " + std::to_string(version) +
                          (version == 1 ? " (version 1 streams, with a page table entry for every page of the padding, "
                                          "are no longer read: encode the volume again)"
                                        : ""));
  const std::size_t bitsAt = r.offset();
  s.sampleBits = r.le<std::uint8_t>("sample_bits");
  if (s.sampleBits != 8 && s.sampleBits != 16)
    r.fail(bitsAt, "sample_bits: expected 8 or 16, got " + std::to_string(s.sampleBits));
  s.grid = LebGrid{r.le<std::uint8_t>("k", 0, kMaxLebK)};
  for (int a = 0; a < 3; ++a)
    s.dims[a] = static_cast<int>(r.le<std::uint32_t>("extent", 1, static_cast<std::uint64_t>(s.grid.pointsPerAxis())));
  if (lebGridCovering(s.dims).k != s.grid.k)
    r.fail(7, "k: " + std::to_string(s.grid.k) + " is not the smallest grid covering " + dimsText(s.dims) +
                  " (expected " + std::to_string(lebGridCovering(s.dims).k) + ")");
  s.pageBits = r.le<std::uint8_t>("page_bits", kMinLebPageBits, kMaxLebPageBits);
  const int channelCount = r.le<std::uint8_t>("channel_count", 1, 2);
  // Byte 22, the coder: the version's (2: lead-1, 3: adaptive, 4: context).
  const std::size_t coderAt = r.offset();
  const int coder = r.le<std::uint8_t>("coder");
  const LebCoder expected = static_cast<LebCoder>(version - kLebVersion);
  if (coder != static_cast<int>(expected))
    r.fail(coderAt, "coder: a version " + std::to_string(version) + " stream has coder " +
                        std::to_string(static_cast<int>(expected)) + " (" +
                        (expected == LebCoder::Lead1 ? std::string("lead-1") : std::string(lebCoderName(expected))) +
                        "), got " + std::to_string(coder));
  s.coder = expected;
  // Byte 23, the gradients: 1 when they are derived from the data (then no gradients channel).
  const std::size_t gradientsAt = r.offset();
  s.derivedGradients = r.le<std::uint8_t>("gradients", 0, 1) == 1;
  if (s.derivedGradients && channelCount != 1)
    r.fail(gradientsAt, "gradients: 1 (derived from the data) with " + std::to_string(channelCount) +
                            " channels: a stream that derives its gradients has the data channel alone");
  const std::size_t totalAt = r.offset();
  const std::uint64_t total = r.le<std::uint64_t>("total_bytes");
  r.le<std::uint32_t>("header_crc");  // checked above
  if (total != b.size())
    r.fail(totalAt, "total_bytes: the header describes " + std::to_string(total) + " bytes, the stream has " +
                        std::to_string(b.size()) + (b.size() < total ? " (truncated)" : " (trailing bytes)"));
  const std::uint64_t pages = s.pageCount();
  // Section 2: channels.
  for (int ci = 0; ci < channelCount; ++ci) {
    LebChannel c;
    c.descriptorOffset = r.offset();
    const std::size_t kindAt = r.offset();
    const int kind = r.le<std::uint8_t>("kind", 0, 1);
    if (kind != ci)
      r.fail(kindAt, "kind: channel " + std::to_string(ci) + " must be " + (ci == 0 ? "0 (data)" : "1 (gradients)"));
    c.kind = static_cast<LebChannelKind>(kind);
    const bool data = c.kind == LebChannelKind::Data;
    c.components = r.le<std::uint8_t>("components", data ? 1 : 3, data ? 1 : 3);
    c.valueBits = r.le<std::uint8_t>("value_bits", data ? static_cast<std::uint64_t>(s.sampleBits) : 8,
                                     data ? static_cast<std::uint64_t>(s.sampleBits) : 8);
    c.isSigned = r.le<std::uint8_t>("signed", data ? 0 : 1, data ? 0 : 1) != 0;
    r.le<std::uint32_t>("page_count", pages, pages);
    const std::uint64_t stored = r.le<std::uint32_t>("stored_pages", 1, pages);
    const std::size_t payloadAt = r.offset();
    const std::uint64_t payload = r.le<std::uint64_t>("payload_bytes");
    if (s.coder == LebCoder::Lead1) {
      const std::size_t tableAt = r.offset();
      const std::string_view table = r.take(lebCodeTableSize(c.valueBits, s.coder), "code lengths");
      c.code.valueBits = c.valueBits;
      c.code.lengths.assign(table.begin(), table.end());
      if (const std::string p = lead1CodeProblem(c.code); !p.empty()) r.fail(tableAt, "code lengths: " + p);
      c.decoder = std::make_shared<const Lead1Decoder>(c.code);
    }
    // The page table: its size is checked against the stream before it is read.
    r.need(static_cast<std::size_t>(stored) * 12 + 4, "page table");
    const std::size_t indicesAt = r.offset();
    c.storedPage.resize(static_cast<std::size_t>(stored));
    for (std::uint64_t j = 0; j < stored; ++j) {
      c.storedPage[j] = r.le<std::uint32_t>("stored page");
      if (c.storedPage[j] >= pages || (j > 0 && c.storedPage[j] <= c.storedPage[j - 1]))
        r.fail(indicesAt + 4 * j,
               "stored page: " + std::to_string(c.storedPage[j]) +
                   (c.storedPage[j] >= pages ? " is not a page of the grid's " + std::to_string(pages)
                                             : " does not follow page " + std::to_string(c.storedPage[j - 1])));
    }
    const std::size_t lengthsAt = r.offset();
    c.pageOffset.assign(static_cast<std::size_t>(stored) + 1, 0);
    for (std::uint64_t i = 0; i < stored; ++i) {
      const std::uint64_t len = r.le<std::uint32_t>("page length");
      c.pageOffset[i + 1] = c.pageOffset[i] + len;
      if (c.pageOffset[i + 1] > payload)
        r.fail(lengthsAt + 4 * i, "page length: page " + std::to_string(c.storedPage[i]) + " ends at byte " +
                                      std::to_string(c.pageOffset[i + 1]) + " of the payload, past its end (" +
                                      std::to_string(payload) + " bytes)");
    }
    if (c.pageOffset.back() != payload)
      r.fail(payloadAt, "payload_bytes: " + std::to_string(payload) + ", but the pages add up to " +
                            std::to_string(c.pageOffset.back()));
    // Every delta costs at least one bit with lead-1 (no code is shorter) and 2^-14 bytes with the
    // adaptive and the context coders (their zero decision: FORMAT.md, "Adaptive pages"), so a
    // stream too short for its volume is refused here, before a decoder allocates anything for it.
    // The context coder's gradients begin with one decision a vector ("Context gradient pages").
    const std::uint64_t deltas = static_cast<std::uint64_t>(sampleCount(s.dims)) *
                                 static_cast<std::uint64_t>(s.coder == LebCoder::Context ? 1 : c.components);
    const std::uint64_t perByte = s.coder == LebCoder::Lead1 ? 8 : kAdaptiveDeltasPerByteBound;
    if (payload < (deltas + perByte - 1) / perByte)
      r.fail(payloadAt, "payload_bytes: " + std::to_string(payload) + " bytes cannot hold the " +
                            std::to_string(deltas) + " deltas of a " + dimsText(s.dims) + " volume (at least " +
                            (s.coder == LebCoder::Lead1 ? "one bit each" : "2^-14 bytes each") + ")");
    c.pageCrc.resize(static_cast<std::size_t>(stored));
    for (std::uint64_t i = 0; i < stored; ++i) c.pageCrc[i] = r.le<std::uint32_t>("page crc");
    const std::size_t crcAt = r.offset();
    if (!crc32Matches(b.substr(c.descriptorOffset, crcAt - c.descriptorOffset), r.le<std::uint32_t>("descriptor crc")))
      r.fail(crcAt, "descriptor crc: CRC-32 mismatch (channel " + std::to_string(ci) + "'s descriptor is corrupt)");
    c.descriptorBytes = r.offset() - c.descriptorOffset;
    c.payloadOffset = r.offset();
    if (payload > r.remaining())
      r.fail(payloadAt, "payload_bytes: " + std::to_string(payload) + " bytes of pages, the stream has " +
                            std::to_string(r.remaining()) + " left");
    r.take(static_cast<std::size_t>(payload), "pages");
    s.channels.push_back(std::move(c));
  }
  if (r.remaining() != 0) r.fail(r.offset(), std::to_string(r.remaining()) + " bytes after the last channel");
  return s;
}

}  // namespace voxref::ref
