// libFuzzer target: the LEB codec's Huffman code tables and the lead-1 page decoder behind them
// (reference/leb/huffman.h, lead1_coder.h). The code tables of an LEB stream are untrusted bytes:
// parseLebStream (leb_stream.cpp) hands a channel's (b+1)^2 code lengths, as read, to
// lead1CodeProblem and then to Lead1Decoder, whose pages are untrusted bytes too. This target
// drives those functions directly, without a stream around them, so that every mutation lands in
// a table or a page.
//
// Input: byte 0 selects the mode and the value bits (bit 0: 8 or 16 bits).
//   mode "decode" (bit 1 clear): the next (b+1)^2 bytes are the code lengths, as the stream stores
//     them; the rest is one page.
//   mode "lengths" (bit 1 set): byte 1 is a length limit (1..kMaxCodeLength), the rest are
//     little-endian u16 symbol counts for huffmanCodeLengths (at most 64 symbols).
// Contract under test:
// - lead1CodeProblem never fails for any lengths; Lead1Decoder accepts exactly the codes it finds
//   no problem with and throws std::invalid_argument for the others;
// - on any page, Lead1PageReader::next / finish and Lead1Decoder::decodePage either decode or
//   throw StreamError; nothing else escapes, nothing reads out of bounds (ASan) or has undefined
//   behaviour (UBSan); every value consumes at least one bit, so decoding stops by itself;
// - a page that decodes completely (finish() accepts it) is exactly what Lead1Encoder writes for
//   the decoded values: decoding and encoding are inverse (canonical codes, zero padding);
// - huffmanCodeLengths gives, for any counts, lengths that codeLengthProblem accepts and
//   canonicalCodes / HuffmanDecodeTable decode back to each symbol, or throws
//   std::invalid_argument when the used symbols cannot fit the limit.
// Size cap: none needed; pages are as long as the input (libFuzzer's -max_len), tables are at
// most 2^kMaxCodeLength entries.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "reference/common/byte_stream.h"
#include "reference/leb/lead1_coder.h"

namespace {

using namespace voxref::ref;

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "contract violated: %s\n", what);
  std::abort();
}

void decodeMode(int valueBits, std::string_view rest) {
  const std::size_t symbols = static_cast<std::size_t>(valueBits + 1);
  if (rest.size() < symbols * symbols) return;
  Lead1Code code;
  code.valueBits = valueBits;
  code.lengths.assign(rest.begin(), rest.begin() + static_cast<std::ptrdiff_t>(symbols * symbols));
  const std::string_view page = rest.substr(symbols * symbols);
  const bool valid = lead1CodeProblem(code).empty();
  std::unique_ptr<Lead1Decoder> decoder;
  try {
    decoder = std::make_unique<Lead1Decoder>(code);
  } catch (const std::invalid_argument&) {
    if (valid) violated("Lead1Decoder refused a code lead1CodeProblem accepts");
    return;
  }
  if (!valid) violated("Lead1Decoder accepted a code lead1CodeProblem refuses");
  // Read values until the page ends (at most one per bit).
  std::vector<std::int32_t> values;
  bool complete = false;
  {
    Lead1PageReader reader(*decoder, page, 100, "fuzz page");
    try {
      while (values.size() <= page.size() * 8) values.push_back(reader.next());
      violated("a page gave more values than it has bits");
    } catch (const StreamError&) {
    }
    try {
      if (reader.valuesRead() != values.size()) violated("valuesRead() disagrees with the values read");
      reader.finish();
      complete = true;
    } catch (const StreamError&) {
    }
  }
  // decodePage of exactly that many values: the same values, or StreamError (leftover bits).
  std::vector<std::int32_t> again(values.size());
  try {
    decoder->decodePage(page, again, 100, "fuzz page");
  } catch (const StreamError&) {
    return;
  }
  if (again != values) violated("decodePage disagrees with Lead1PageReader");
  if (!complete) return;
  BitWriter out;
  Lead1Encoder(code).encodePage(values, out);  // std::invalid_argument would be a finding
  if (out.finish() != page) violated("encodePage(decodePage(page)) != page");
}

void lengthsMode(std::string_view rest) {
  if (rest.empty()) return;
  const int limit = 1 + static_cast<unsigned char>(rest[0]) % kMaxCodeLength;
  std::vector<std::uint64_t> counts;
  for (std::size_t i = 1; i + 1 < rest.size() && counts.size() < 64; i += 2)
    counts.push_back(loadLe(rest.data() + i, 2));
  std::vector<std::uint8_t> lengths;
  try {
    lengths = huffmanCodeLengths(counts, limit);
  } catch (const std::invalid_argument&) {
    std::size_t used = 0;
    for (std::uint64_t c : counts) used += c > 0;
    if (used <= (std::size_t{1} << limit)) violated("huffmanCodeLengths refused symbols that fit");
    return;
  }
  if (lengths.size() != counts.size()) violated("one length per count");
  for (std::size_t s = 0; s < counts.size(); ++s)
    if ((counts[s] == 0) != (lengths[s] == 0)) violated("a used symbol without a code, or an unused one with a code");
  if (!codeLengthProblem(lengths, limit).empty()) violated("huffmanCodeLengths gave lengths codeLengthProblem refuses");
  const HuffmanDecodeTable table(lengths);
  const std::vector<std::uint32_t> codes = canonicalCodes(lengths);
  for (std::size_t s = 0; s < lengths.size(); ++s) {
    if (!lengths[s]) continue;
    const std::uint16_t e = table.entry(codes[s] << (table.bits() - lengths[s]));
    if (e != ((s << 4) | lengths[s])) violated("the decode table does not give back a symbol's code");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string_view rest(reinterpret_cast<const char*>(data) + 1, size - 1);
  const int valueBits = (data[0] & 1) ? 16 : 8;
  if (data[0] & 2)
    lengthsMode(rest);
  else
    decodeMode(valueBits, rest);
  return 0;
}
