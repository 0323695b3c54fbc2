#include "reference/leb/lead1_coder.h"

#include <algorithm>
#include <exception>
#include <stdexcept>

#include "reference/common/byte_stream.h"

namespace voxref::ref {

Lead1Counter::Lead1Counter(int valueBits)
    : valueBits_(valueBits), counts_(static_cast<std::size_t>((valueBits + 1) * (valueBits + 1)), 0) {}

void Lead1Counter::add(std::span<const std::int32_t> page) {
  const int symbols = valueBits_ + 1;
  int context = 0;
  for (std::int32_t d : page) {
    const int s = lead1Symbol(d);
    ++counts_[static_cast<std::size_t>(context * symbols + s)];
    context = s;
  }
}

void Lead1Counter::merge(const Lead1Counter& other) {
  for (std::size_t i = 0; i < counts_.size(); ++i) counts_[i] += other.counts_[i];
}

Lead1Code Lead1Counter::code() const {
  Lead1Code c;
  c.valueBits = valueBits_;
  const std::size_t symbols = static_cast<std::size_t>(valueBits_ + 1);
  for (std::size_t ctx = 0; ctx < symbols; ++ctx) {
    const auto l =
        huffmanCodeLengths(std::span<const std::uint64_t>(counts_).subspan(ctx * symbols, symbols), kMaxCodeLength);
    c.lengths.insert(c.lengths.end(), l.begin(), l.end());
  }
  return c;
}

std::string lead1CodeProblem(const Lead1Code& code) {
  if (code.valueBits != 8 && code.valueBits != 16)
    return "value bits must be 8 or 16, got " + std::to_string(code.valueBits);
  const std::size_t symbols = static_cast<std::size_t>(code.symbols());
  if (code.lengths.size() != symbols * symbols)
    return "the code table needs " + std::to_string(symbols * symbols) + " lengths";
  for (std::size_t ctx = 0; ctx < symbols; ++ctx) {
    const std::string p =
        codeLengthProblem(std::span<const std::uint8_t>(code.lengths).subspan(ctx * symbols, symbols), kMaxCodeLength);
    if (!p.empty()) return "context " + std::to_string(ctx) + ": " + p;
  }
  return "";
}

Lead1Encoder::Lead1Encoder(const Lead1Code& code)
    : valueBits_(code.valueBits), symbols_(code.symbols()), lengths_(code.lengths) {
  if (const std::string p = lead1CodeProblem(code); !p.empty()) throw std::invalid_argument("lead-1 code: " + p);
  for (int ctx = 0; ctx < symbols_; ++ctx) {
    const auto c = canonicalCodes(std::span<const std::uint8_t>(lengths_).subspan(
        static_cast<std::size_t>(ctx * symbols_), static_cast<std::size_t>(symbols_)));
    codes_.insert(codes_.end(), c.begin(), c.end());
  }
}

void Lead1Encoder::encodePage(std::span<const std::int32_t> deltas, BitWriter& out) const {
  const std::int32_t lo = -(1 << (valueBits_ - 1)), hi = (1 << (valueBits_ - 1)) - 1;
  int context = 0;
  for (std::int32_t d : deltas) {
    if (d < lo || d > hi)
      throw std::invalid_argument("delta " + std::to_string(d) + " is outside the " + std::to_string(valueBits_) +
                                  "-bit range");
    const int s = lead1Symbol(d);
    const std::size_t at = static_cast<std::size_t>(context * symbols_ + s);
    if (lengths_[at] == 0)
      throw std::invalid_argument("symbol " + std::to_string(s) + " has no code in context " + std::to_string(context));
    out.put(codes_[at], lengths_[at]);
    if (s > 0) {
      const std::uint32_t m = static_cast<std::uint32_t>(d < 0 ? -d : d);
      // Sign, then the bits below the leading one: s bits in all.
      out.put(((d < 0 ? 1u : 0u) << (s - 1)) | (m & ((1u << (s - 1)) - 1)), s);
    }
    context = s;
  }
}

Lead1Decoder::Lead1Decoder(const Lead1Code& code) : valueBits_(code.valueBits), symbols_(code.symbols()) {
  if (const std::string p = lead1CodeProblem(code); !p.empty()) throw std::invalid_argument("lead-1 code: " + p);
  for (int ctx = 0; ctx < symbols_; ++ctx)
    tables_.emplace_back(std::span<const std::uint8_t>(code.lengths)
                             .subspan(static_cast<std::size_t>(ctx * symbols_), static_cast<std::size_t>(symbols_)));
  // The one-lookup entries: every kFastBits-bit window that starts with a whole code of the
  // context (its sign and magnitude may run past the window), except symbol valueBits, whose
  // magnitude the table path checks (Lead1SignMagnitude::fits: below it every magnitude is in range, so under
  // 2^15 and the delta fits the entry's 16 bits). A value wholly in the window carries its delta.
  constexpr int F = kFastBits;
  fast_.assign(static_cast<std::size_t>(symbols_) << F, 0);
  for (int ctx = 0; ctx < symbols_; ++ctx) {
    const HuffmanDecodeTable& t = tables_[static_cast<std::size_t>(ctx)];
    if (t.empty()) continue;
    for (std::uint32_t window = 0; window < (1u << F); ++window) {
      const std::uint16_t e = t.entry(t.bits() <= F ? window >> (F - t.bits()) : window << (t.bits() - F));
      const int length = e & 15, s = e >> 4;
      if (e == 0 || length > F || s == valueBits_) continue;
      const int total = length + s;
      std::uint32_t entry = static_cast<std::uint32_t>(total | s << 5);
      if (total <= F)
        entry |= kWholeValue |
                 static_cast<std::uint32_t>(static_cast<std::uint16_t>(fastDelta(entry, window >> (F - total)))) << 16;
      fast_[(static_cast<std::size_t>(ctx) << F) | window] = entry;
    }
  }
  // Pairs: a window whose first value lies wholly in it, followed by a second (in the first's
  // symbol as context) that does too. The second's entry is looked up with zero bits shifted in
  // behind the window; it depends only on its own bits, which all lie in the window.
  std::vector<std::uint32_t> pairs(fast_.size(), 0);
  for (std::size_t at = 0; at < fast_.size(); ++at) {
    const std::uint32_t first = fast_[at];
    if (!(first & kWholeValue)) continue;
    const int length = static_cast<int>(first & 31), context = symbolOf(first);
    const std::uint32_t window = static_cast<std::uint32_t>(at) & ((1u << F) - 1);
    const std::uint32_t second = fastEntry(context, (window << length) & ((1u << F) - 1));
    if (!(second & kWholeValue) || length + static_cast<int>(second & 31) > F) continue;
    const auto bits10 = [](std::uint32_t e) { return static_cast<std::uint32_t>(wholeDelta(e)) & 1023u; };
    pairs[at] = (static_cast<std::uint32_t>(length) + (second & 31)) | (second & (31u << 5)) | kPair |
                bits10(first) << 12 | bits10(second) << 22;
  }
  for (std::size_t at = 0; at < fast_.size(); ++at)
    if (pairs[at] != 0) fast_[at] = pairs[at];
  std::uint32_t longest = 1;
  for (const std::uint32_t e : fast_) longest = std::max(longest, e & 31);
  lookupsPerRefill_ = std::max(1, 56 / static_cast<int>(longest));
}

void Lead1Decoder::decodePage(std::string_view page, std::span<std::int32_t> out, std::size_t streamOffset,
                              std::string_view what) const {
  Lead1PageReader r(*this, page, streamOffset, std::string(what));
  r.read(out);
  r.finish();
}

Lead1PageReader::Lead1PageReader(const Lead1Decoder& decoder, std::string_view page, std::size_t streamOffset,
                                 std::string what)
    : decoder_(&decoder), page_(page), in_(page), streamOffset_(streamOffset), what_(std::move(what)) {}

template <int K>
void Lead1PageReader::lookupRuns(const Lead1Decoder& d, BitReader& in, int& context, std::span<std::int32_t> out,
                                 std::size_t& i) {
  while (i + 2 * K <= out.size()) {
    for (int k = 0; k < K; ++k) {
      const std::uint32_t e = d.fastEntry(context, in.peek(Lead1Decoder::kFastBits));
      if (e == 0) {
        in.refill();
        return;
      }
      fastStep<false>(e, in, context, out.data(), i);
    }
    in.refill();
  }
}

void Lead1PageReader::read(std::span<std::int32_t> out) {
  std::size_t i = 0;
  const int perRefill = decoder_->lookupsPerRefill();
  while (i < out.size()) {
    // A run of one-lookup values on local copies (registers), then one value by the table path.
    BitReader in = in_;
    int context = context_;
    const std::size_t start = i;
    if (perRefill >= 3)
      lookupRuns<3>(*decoder_, in, context, out, i);
    else if (perRefill == 2)
      lookupRuns<2>(*decoder_, in, context, out, i);
    while (i < out.size()) {
      const std::uint32_t e = decoder_->fastEntry(context, in.peek(Lead1Decoder::kFastBits));
      if (e == 0) break;
      if ((e & Lead1Decoder::kPair) && i + 1 == out.size()) break;  // room for one: the table path takes it
      fastStep(e, in, context, out.data(), i);
    }
    if (in.overrun()) [[unlikely]]
      for (std::size_t j = start; j < i; ++j) (void)next();  // replays the run to throw at its value
    commitRun(in, context, i - start);
    if (i < out.size()) out[i++] = nextByTable();
  }
}

template <int K>
void Lead1PageReader::lookupRunsBoth(const Lead1Decoder& da, BitReader& inA, int& contextA,
                                     std::span<std::int32_t> outA, std::size_t& i, const Lead1Decoder& db,
                                     BitReader& inB, int& contextB, std::span<std::int32_t> outB, std::size_t& j) {
  while (i + 2 * K <= outA.size() && j + 2 * K <= outB.size()) {
    for (int k = 0; k < K; ++k) {
      const std::uint32_t ea = da.fastEntry(contextA, inA.peek(Lead1Decoder::kFastBits));
      const std::uint32_t eb = db.fastEntry(contextB, inB.peek(Lead1Decoder::kFastBits));
      if (ea == 0 || eb == 0) {
        inA.refill();
        inB.refill();
        return;
      }
      fastStep<false>(ea, inA, contextA, outA.data(), i);
      fastStep<false>(eb, inB, contextB, outB.data(), j);
    }
    inA.refill();
    inB.refill();
  }
}

void Lead1PageReader::readBoth(Lead1PageReader& a, std::span<std::int32_t> outA, Lead1PageReader& b,
                               std::span<std::int32_t> outB) {
  std::size_t i = 0, j = 0;
  const int perRefill = std::min(a.decoder_->lookupsPerRefill(), b.decoder_->lookupsPerRefill());
  std::exception_ptr bFailed;  // b's error waits for the rest of a, whose own error comes first
  // Runs of one-lookup values of both pages on local copies, while each has room for a pair; a run
  // ends where either page's next value needs the table path.
  while (i + 1 < outA.size() && j + 1 < outB.size()) {
    BitReader inA = a.in_, inB = b.in_;
    int contextA = a.context_, contextB = b.context_;
    const std::size_t i0 = i, j0 = j;
    bool tableA = false, tableB = false;
    if (perRefill >= 3)
      lookupRunsBoth<3>(*a.decoder_, inA, contextA, outA, i, *b.decoder_, inB, contextB, outB, j);
    else if (perRefill == 2)
      lookupRunsBoth<2>(*a.decoder_, inA, contextA, outA, i, *b.decoder_, inB, contextB, outB, j);
    while (i + 1 < outA.size() && j + 1 < outB.size()) {
      const std::uint32_t ea = a.decoder_->fastEntry(contextA, inA.peek(Lead1Decoder::kFastBits));
      const std::uint32_t eb = b.decoder_->fastEntry(contextB, inB.peek(Lead1Decoder::kFastBits));
      if (ea == 0 || eb == 0) {
        tableA = ea == 0;
        tableB = eb == 0;
        break;
      }
      fastStep(ea, inA, contextA, outA.data(), i);
      fastStep(eb, inB, contextB, outB.data(), j);
    }
    if (inA.overrun() || inB.overrun()) {  // read() from the run's start names the value
      i = i0;
      j = j0;
      break;
    }
    a.commitRun(inA, contextA, i - i0);
    b.commitRun(inB, contextB, j - j0);
    if (tableA) outA[i++] = a.nextByTable();
    if (tableB) {
      try {
        outB[j++] = b.nextByTable();
      } catch (...) {
        bFailed = std::current_exception();
        break;
      }
    }
  }
  a.read(outA.subspan(i));
  if (bFailed) std::rethrow_exception(bFailed);
  b.read(outB.subspan(j));
}

void Lead1PageReader::fail(const std::string& detail) const {
  throw StreamError(streamOffset_ + std::min(page_.size(), in_.bitsConsumed() / 8),
                    what_ + ": value " + std::to_string(read_) + ": " + detail);
}

std::int32_t Lead1PageReader::nextByTable() {
  const HuffmanDecodeTable& t = decoder_->tables_[static_cast<std::size_t>(context_)];
  if (t.empty())
    fail("context " + std::to_string(context_) + " has no codes, yet a value follows a symbol " +
         std::to_string(context_));
  const std::uint16_t e = t.entry(in_.peek(t.bits()));
  if (e == 0)
    fail("the next " + std::to_string(t.bits()) + " bits match no code of context " + std::to_string(context_));
  const int s = e >> 4;
  in_.skip(e & 15);
  std::int32_t d = 0;
  if (s > 0) {
    const std::uint32_t bits = in_.get(s);
    if (in_.overrun()) fail("the page ends inside this value");
    const Lead1SignMagnitude v = lead1SignMagnitude(bits, s);
    if (!v.fits(decoder_->valueBits_))
      fail("delta " + std::string(v.negative ? "-" : "+") + std::to_string(v.magnitude) + " is outside the " +
           std::to_string(decoder_->valueBits_) + "-bit range");
    d = v.delta();
  }
  if (in_.overrun()) fail("the page ends inside this value");
  ++read_;
  context_ = s;
  return d;
}

void Lead1PageReader::finish() const {
  const std::size_t used = in_.bitsConsumed(), total = page_.size() * 8;
  if (total - used >= 8)
    throw StreamError(streamOffset_ + (used + 7) / 8, what_ + ": " + std::to_string(page_.size() - (used + 7) / 8) +
                                                          " bytes left over after the last value");
  if (used < total && (static_cast<unsigned char>(page_.back()) & ((1u << (total - used)) - 1)) != 0)
    throw StreamError(streamOffset_ + page_.size() - 1, what_ + ": the padding bits after the last value are not zero");
}

}  // namespace voxref::ref
