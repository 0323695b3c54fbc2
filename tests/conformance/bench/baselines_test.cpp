#include "conformance/bench/baselines.h"

#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace voxref::conf {
namespace {

// A stand-in coder that records what it was given: half a byte a byte, rounded up, and a time a
// piece of its length in seconds, so that the sums can be derived by hand.
struct RecordingCoder {
  std::vector<std::string> pieces;
  BaselineResult operator()(std::string_view piece) {
    pieces.emplace_back(piece);
    const double s = static_cast<double>(piece.size());
    return {"half", (piece.size() + 1) / 2, Timing{s, s, s, 3, false}, Timing{2 * s, s, 3 * s, 5, false}};
  }
};

TEST(PiecewiseBaseline, CutsTheBytesIntoPiecesAndSumsWhatEachCost) {
  RecordingCoder coder;
  const BaselineResult r = piecewiseBaseline("0123456789", 4, [&](std::string_view p) { return coder(p); });
  EXPECT_EQ(coder.pieces, (std::vector<std::string>{"0123", "4567", "89"}));
  EXPECT_EQ(r.codec, "half on pieces of 4 bytes");
  EXPECT_EQ(r.bytes, 2u + 2u + 1u);
  EXPECT_DOUBLE_EQ(r.compress.median, 10.0);
  EXPECT_DOUBLE_EQ(r.decompress.median, 20.0);
  EXPECT_DOUBLE_EQ(r.decompress.min, 10.0);
  EXPECT_DOUBLE_EQ(r.decompress.max, 30.0);
  EXPECT_EQ(r.compress.runs, 3);
  EXPECT_EQ(r.decompress.runs, 5);
}

TEST(PiecewiseBaseline, OnePieceWhenThePieceHoldsEverything) {
  RecordingCoder coder;
  const BaselineResult r = piecewiseBaseline("abc", 1 << 16, [&](std::string_view p) { return coder(p); });
  EXPECT_EQ(coder.pieces, std::vector<std::string>{"abc"});
  EXPECT_EQ(r.bytes, 2u);
}

TEST(PiecewiseBaseline, RefusesEmptyPiecesAndEmptyInput) {
  auto coder = [](std::string_view) { return BaselineResult{"x", 1, {}, {}}; };
  EXPECT_THROW(piecewiseBaseline("abc", 0, coder), std::invalid_argument);
  EXPECT_THROW(piecewiseBaseline("", 4, coder), std::invalid_argument);
}

// zstd on two pieces that are the same bytes: each piece is its own frame, so the pieces cost
// twice what one costs, where the whole input would have copied the second from the first.
TEST(PiecewiseBaseline, EachPieceIsCodedOnItsOwn) {
  std::string piece;
  for (int i = 0; i < 4096; ++i) piece.push_back(static_cast<char>((i * 7919) % 251));
  const BaselineResult one = zstdBaseline(piece, 3);
  const BaselineResult two =
      piecewiseBaseline(piece + piece, piece.size(), [](std::string_view p) { return zstdBaseline(p, 3); });
  EXPECT_EQ(two.bytes, 2 * one.bytes);
  EXPECT_LT(zstdBaseline(piece + piece, 3).bytes, two.bytes);
}

// The frame a bench times taking turns: zstd's own frame of the bytes (zstdBaseline's size), and
// every decode gives the bytes back, the first decode after the constructor's check too.
TEST(ZstdFrame, DecodesTheBytesItWasGivenEveryTime) {
  std::string raw;
  for (int i = 0; i < 100000; ++i) raw.push_back(static_cast<char>("abcab"[i % 5] + (i % 977 == 0)));
  ZstdFrame frame(raw, 19);
  EXPECT_EQ(frame.rawBytes(), raw.size());
  EXPECT_EQ(frame.bytes(), zstdBaseline(raw, 19).bytes);
  EXPECT_LT(frame.bytes(), raw.size() / 20);  // a period of 5 with a mark every 977 bytes
  for (int run = 0; run < 3; ++run) {
    frame.decode();
    EXPECT_EQ(frame.decoded(), raw);
  }
  ZstdFrame empty("", 3);
  empty.decode();
  EXPECT_TRUE(empty.decoded().empty());
}

}  // namespace
}  // namespace voxref::conf
