#include "reference/leb/lead1_coder.h"

#include <algorithm>
#include <bit>
#include <random>

#include <gtest/gtest.h>

#include "reference/common/byte_stream.h"

namespace voxref::ref {
namespace {

std::string errorOf(const Lead1Decoder& d, std::string_view page, std::size_t count) {
  std::vector<std::int32_t> out(count);
  try {
    d.decodePage(page, out, 100, "test page");
  } catch (const StreamError& e) {
    return e.what();
  }
  return "";
}

TEST(Lead1, SymbolIsThePositionOfTheLeadingOne) {
  EXPECT_EQ(lead1Symbol(0), 0);
  EXPECT_EQ(lead1Symbol(1), 1);
  EXPECT_EQ(lead1Symbol(-1), 1);
  EXPECT_EQ(lead1Symbol(5), 3);  // the paper's example 00000101: leading one in bit 3
  EXPECT_EQ(lead1Symbol(127), 7);
  EXPECT_EQ(lead1Symbol(-128), 8);
  EXPECT_EQ(lead1Symbol(-32768), 16);
}

TEST(Lead1, BitsOfOneValueFollowTheFormat) {
  // One context-0 code where symbol 3 has the code "1" and symbol 0 the code "0" (others unused).
  Lead1Code code;
  code.valueBits = 8;
  code.lengths.assign(81, 0);
  code.lengths[0] = 1;          // context 0, symbol 0
  code.lengths[3] = 1;          // context 0, symbol 3
  code.lengths[3 * 9 + 0] = 1;  // context 3: symbols 0 and 3
  code.lengths[3 * 9 + 3] = 1;
  BitWriter w;
  const std::int32_t deltas[] = {-5};
  Lead1Encoder(code).encodePage(deltas, w);
  // code 1, sign 1, then 01 (5 = 101 below its leading one): 1101, padded with zeros.
  EXPECT_EQ(w.finish(), std::string(1, static_cast<char>(0b11010000)));
}

class Lead1RoundTrip : public ::testing::TestWithParam<int> {};

TEST_P(Lead1RoundTrip, RandomDeltasIncludingTheExtremes) {
  const int bits = GetParam();
  std::mt19937 rng(static_cast<unsigned>(bits));
  const std::int32_t lo = -(1 << (bits - 1)), hi = (1 << (bits - 1)) - 1;
  std::vector<std::vector<std::int32_t>> pages(5);
  for (auto& p : pages) {
    for (int i = 0; i < 3000; ++i) {
      const int mag = static_cast<int>(rng() % static_cast<unsigned>(bits));  // geometric-ish spread of symbols
      p.push_back(std::clamp(static_cast<std::int32_t>((rng() % (1u << mag)) * ((rng() & 1) ? 1 : -1)), lo, hi));
    }
    p.push_back(lo);
    p.push_back(hi);
    p.push_back(0);
  }
  Lead1Counter counter(bits);
  for (const auto& p : pages) counter.add(p);
  const Lead1Code code = counter.code();
  ASSERT_EQ(lead1CodeProblem(code), "");
  const Lead1Encoder enc(code);
  const Lead1Decoder dec(code);
  for (const auto& p : pages) {
    BitWriter w;
    enc.encodePage(p, w);
    const std::string bytes = w.finish();
    std::vector<std::int32_t> back(p.size());
    dec.decodePage(bytes, back, 0, "page");
    EXPECT_EQ(back, p);
    // read() (runs of one-lookup values in registers) against next() one value at a time, in
    // chunks of every size, and on truncated pages: the same values, the same error.
    for (std::size_t chunk : {std::size_t{1}, std::size_t{7}, std::size_t{768}, p.size()}) {
      Lead1PageReader byRead(dec, bytes, 0, "page");
      std::vector<std::int32_t> got;
      for (std::size_t at = 0; at < p.size(); at += chunk) {
        std::vector<std::int32_t> part(std::min(chunk, p.size() - at));
        byRead.read(part);
        got.insert(got.end(), part.begin(), part.end());
      }
      EXPECT_EQ(got, p) << "chunk " << chunk;
    }
    for (std::size_t cut = 1; cut < bytes.size(); cut += bytes.size() / 5) {
      const std::string_view shorter = std::string_view(bytes).substr(0, bytes.size() - cut);
      auto errorOfReader = [&](bool whole) -> std::string {
        Lead1PageReader r(dec, shorter, 0, "page");
        try {
          if (whole) {
            std::vector<std::int32_t> all(p.size());
            r.read(all);
          } else {
            for (std::size_t i = 0; i < p.size(); ++i) (void)r.next();
          }
        } catch (const StreamError& e) {
          return e.what();
        }
        return "";
      };
      const std::string e = errorOfReader(false);
      EXPECT_NE(e, "") << "cut " << cut;
      EXPECT_EQ(errorOfReader(true), e) << "cut " << cut;
    }
  }
}

// readBoth against a.read then b.read, one after the other: the same values, in the same places
// of both pages (next() then goes on from there alike), and the same error where either page is
// cut short (a's first). Pages of the same code, in prefixes of every length class (one value, room
// for a pair's first only, a run, the whole page).
TEST_P(Lead1RoundTrip, ReadBothEqualsTheTwoReadsOneAfterTheOther) {
  const int bits = GetParam();
  std::mt19937 rng(static_cast<unsigned>(100 + bits));
  std::vector<std::vector<std::int32_t>> pages(4);
  Lead1Counter counter(bits);
  for (std::size_t i = 0; i < pages.size(); ++i) {
    // Pages of small deltas (pairs), and pages of mostly zeros with rare wide deltas and the extreme
    // -2^(b-1), whose long codes and symbol b take the table path.
    for (int v = 0; v < 2000; ++v) {
      const bool rare = i % 2 == 1 && rng() % 16 == 0;
      const int mag = static_cast<int>(rng() % static_cast<unsigned>(rare ? bits - 1 : 3));
      std::int32_t d = static_cast<std::int32_t>((rng() % (1u << mag)) * ((rng() & 1) ? 1 : -1));
      if (i % 2 == 1 && !rare) d = 0;
      if (rare && rng() % 8 == 0) d = -(1 << (bits - 1));
      pages[i].push_back(d);
    }
    counter.add(pages[i]);
  }
  const Lead1Code code = counter.code();
  const Lead1Encoder enc(code);
  const Lead1Decoder dec(code);
  std::vector<std::string> bytes;
  for (const auto& p : pages) {
    BitWriter w;
    enc.encodePage(p, w);
    bytes.push_back(w.finish());
  }
  struct Outcome {
    std::vector<std::int32_t> a, b, nextA, nextB;
    std::string error;
    bool operator==(const Outcome&) const = default;
  };
  auto run = [&](std::string_view pa, std::string_view pb, std::size_t na, std::size_t nb, bool both) {
    Lead1PageReader ra(dec, pa, 0, "page a"), rb(dec, pb, 0, "page b");
    Outcome o;
    o.a.resize(na);
    o.b.resize(nb);
    try {
      if (both) {
        Lead1PageReader::readBoth(ra, o.a, rb, o.b);
      } else {
        ra.read(o.a);
        rb.read(o.b);
      }
      for (int i = 0; i < 5; ++i) {
        o.nextA.push_back(ra.next());
        o.nextB.push_back(rb.next());
      }
    } catch (const StreamError& e) {
      o = Outcome{};  // what an error leaves in the outputs is not part of the contract
      o.error = e.what();
    }
    return o;
  };
  int errors = 0;
  for (std::size_t x = 0; x < pages.size(); ++x)
    for (std::size_t y = 0; y < pages.size(); ++y)
      for (std::size_t na : {std::size_t{1}, std::size_t{2}, std::size_t{777}, std::size_t{1995}})
        for (std::size_t nb : {std::size_t{1}, std::size_t{2}, std::size_t{1000}, std::size_t{1995}}) {
          SCOPED_TRACE("pages " + std::to_string(x) + ", " + std::to_string(y) + ": " + std::to_string(na) + " and " +
                       std::to_string(nb) + " values");
          const Outcome whole = run(bytes[x], bytes[y], na, nb, true);
          EXPECT_EQ(whole, run(bytes[x], bytes[y], na, nb, false));
          EXPECT_EQ(whole.error, "");
          EXPECT_TRUE(std::equal(whole.a.begin(), whole.a.end(), pages[x].begin()));
        }
  // Cut short, at fifteen places of each page: one page, the other, or both fail, at a value of
  // the one-lookup path or of the table path; a's error comes first.
  for (std::size_t x = 0; x < pages.size(); ++x)
    for (std::size_t y = 0; y < pages.size(); ++y)
      for (std::size_t t = 0; t < 16; ++t)
        for (std::size_t u = 0; u < 16; ++u) {
          if (t == 0 && u == 0) continue;
          SCOPED_TRACE("pages " + std::to_string(x) + ", " + std::to_string(y) + " cut at " + std::to_string(t) +
                       "/16 and " + std::to_string(u) + "/16");
          const std::string_view pa = std::string_view(bytes[x]).substr(
                                     0, t == 0 ? bytes[x].size() : bytes[x].size() * t / 16),
                                 pb = std::string_view(bytes[y]).substr(
                                     0, u == 0 ? bytes[y].size() : bytes[y].size() * u / 16);
          const Outcome cut = run(pa, pb, pages[x].size(), pages[y].size(), true);
          EXPECT_EQ(cut, run(pa, pb, pages[x].size(), pages[y].size(), false));
          errors += cut.error.empty() ? 0 : 1;
        }
  EXPECT_GT(errors, 100) << "too few of the cut pages failed: the errors were not compared";
}

// read() and readBoth() take up to lookupsPerRefill() one-lookup entries between two refills of
// their bits, and a refill leaves at least 56 (bit_stream.h): so many of the longest entry must fit
// in 56 bits, or a run would peek past the buffered bits. The longest entry is found here from the
// table itself, every context and every window, for a code where wide symbols are rare (their codes
// long, so entries long).
TEST_P(Lead1RoundTrip, LookupsBetweenRefillsFitTheBufferedBits) {
  const int bits = GetParam();
  std::mt19937 rng(static_cast<unsigned>(200 + bits));
  std::vector<std::int32_t> deltas;
  for (int i = 0; i < 50000; ++i) {
    const int mag = std::min(std::countr_zero(rng() | (1u << (bits - 1))), bits - 1);  // symbol s: about 2^-s
    deltas.push_back(static_cast<std::int32_t>(((1 << mag) | (rng() % (1u << mag))) * ((rng() & 1) ? 1 : -1)) / 2);
  }
  Lead1Counter counter(bits);
  counter.add(deltas);
  const Lead1Code code = counter.code();
  const Lead1Decoder dec(code);
  std::uint32_t longest = 0;
  for (int context = 0; context < code.symbols(); ++context)
    for (std::uint32_t window = 0; window < (1u << Lead1Decoder::kFastBits); ++window)
      longest = std::max(longest, dec.fastEntry(context, window) & 31);
  ASSERT_GT(longest, 10u) << "no entry reads past its window: the bound was not tested";
  EXPECT_LE(static_cast<std::uint32_t>(dec.lookupsPerRefill()) * longest, 56u);
  EXPECT_GT(static_cast<std::uint32_t>(dec.lookupsPerRefill() + 1) * longest, 56u);
  EXPECT_GE(dec.lookupsPerRefill(), 2);
  // And the values of such pages: read() against next(), one value at a time.
  BitWriter w;
  Lead1Encoder(code).encodePage(deltas, w);
  const std::string page = w.finish();
  std::vector<std::int32_t> back(deltas.size());
  Lead1PageReader(dec, page, 0, "page").read(back);
  Lead1PageReader one(dec, page, 0, "page");
  for (std::size_t i = 0; i < deltas.size(); ++i) ASSERT_EQ(one.next(), deltas[i]) << "value " << i;
  EXPECT_EQ(back, deltas);
}

INSTANTIATE_TEST_SUITE_P(Bits, Lead1RoundTrip, ::testing::Values(8, 16));

class Lead1Corrupt : public ::testing::Test {
 protected:
  void SetUp() override {
    Lead1Counter c(8);
    c.add(deltas);
    code = c.code();
    BitWriter w;
    Lead1Encoder(code).encodePage(deltas, w);
    page = w.finish();
  }
  std::vector<std::int32_t> deltas{0, 1, -1, 3, 0, 0, 7, -100, 2, 0, 1, 1, 0, -128, 127};
  Lead1Code code;
  std::string page;
};

TEST_F(Lead1Corrupt, TruncatedPageEndsInsideAValue) {
  const Lead1Decoder d(code);
  EXPECT_EQ(errorOf(d, page, deltas.size()), "");
  const std::string e = errorOf(d, std::string_view(page).substr(0, page.size() - 2), deltas.size());
  EXPECT_NE(e.find("the page ends inside this value"), std::string::npos) << e;
  EXPECT_NE(e.find("test page: value "), std::string::npos) << e;
}

TEST_F(Lead1Corrupt, LeftOverBytesAndNonZeroPadding) {
  const Lead1Decoder d(code);
  EXPECT_NE(errorOf(d, page + std::string(2, '\0'), deltas.size()).find("2 bytes left over after the last value"),
            std::string::npos);
  std::vector<std::int32_t> shorter(deltas.begin(), deltas.end() - 1);
  // Decoding fewer values than the page holds leaves bits over as well.
  EXPECT_NE(errorOf(d, page, shorter.size()), "");
}

TEST_F(Lead1Corrupt, ACodeThatIsNotPrefixFreeIsRefused) {
  Lead1Code bad = code;
  for (int s = 0; s < 9; ++s) bad.lengths[static_cast<std::size_t>(s)] = 1;  // nine 1-bit codes in context 0
  EXPECT_NE(lead1CodeProblem(bad).find("context 0: the code lengths are not those of a prefix-free code"),
            std::string::npos);
  EXPECT_THROW(Lead1Decoder{bad}, std::invalid_argument);
}

TEST_F(Lead1Corrupt, ASymbolPastTheTable) {
  // Context 0 knows only symbols 0 and 1 (codes 0 and 10); the bits 11 match nothing.
  Lead1Code sparse;
  sparse.valueBits = 8;
  sparse.lengths.assign(81, 0);
  sparse.lengths[0] = 1;
  sparse.lengths[1] = 2;
  const Lead1Decoder d(sparse);
  const std::string e = errorOf(d, std::string(1, static_cast<char>(0b11000000)), 1);
  EXPECT_NE(e.find("the next 2 bits match no code of context 0"), std::string::npos) << e;
  // A value after symbol 0 needs context 0; after symbol 1, context 1 has no codes at all.
  const std::string e2 = errorOf(d, std::string(1, static_cast<char>(0b10000000)), 2);
  EXPECT_NE(e2.find("context 1 has no codes"), std::string::npos) << e2;
}

TEST_F(Lead1Corrupt, PlusTwoToTheSevenIsOutsideTheRange) {
  Lead1Code c8;
  c8.valueBits = 8;
  c8.lengths.assign(81, 0);
  c8.lengths[0] = 1;  // context 0: symbol 0 has the code "0"
  c8.lengths[8] = 1;  // and symbol 8 the code "1"
  const Lead1Decoder d(c8);
  // code 1, sign 0 (positive), then seven zero bits: +128.
  const std::string e = errorOf(d, std::string{static_cast<char>(0x80), '\0'}, 1);
  EXPECT_NE(e.find("delta +128 is outside the 8-bit range"), std::string::npos) << e;
}

}  // namespace
}  // namespace voxref::ref
