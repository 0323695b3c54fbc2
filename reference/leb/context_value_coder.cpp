#include "reference/leb/context_value_coder.h"

#include <algorithm>
#include <stdexcept>

#include "reference/common/byte_stream.h"

namespace voxref::ref {

namespace {

int checkedValueBits(int valueBits) {
  if (valueBits != 8 && valueBits != 16)
    throw std::invalid_argument("context coder: value bits must be 8 or 16, got " + std::to_string(valueBits));
  return valueBits;
}

}  // namespace

ContextPageState::ContextPageState(int valueBits, int pageBits, std::uint64_t page)
    : models_(checkedValueBits(valueBits), kContextContexts, kContextSignContexts),
      begin_(page << pageBits),
      signedSymbol_(std::size_t{1} << pageBits, 0) {}

ContextPageState::Contexts ContextPageState::contexts(const HzOrder& order, std::uint64_t h, const GridPoint& p,
                                                      const LebPointClass& c, int rangeBucket) const {
  // FORMAT.md, "Context pages": the neighbours of p's own class at -2h on each axis. They are of
  // p's level and precede it in the hierarchical order; those of an earlier page do not count, so
  // that a page depends on no other page of its scale.
  std::uint64_t below[3];
  order.indicesBelow(h, p, c, below);
  int symbols = 0, signs = 0;
  for (const std::uint64_t hq : below) {
    if (hq == HzOrder::kNoIndex || hq < begin_ || hq - begin_ >= signedSymbol_.size()) continue;
    const int s = signedSymbol_[static_cast<std::size_t>(hq - begin_)];
    symbols += s < 0 ? -s : s;
    signs += (s > 0) - (s < 0);
  }
  return {std::min(symbols, kContextNeighbourSums - 1) * kContextRangeBuckets + rangeBucket,
          std::clamp(signs, -3, 3) + 3};
}

void ContextPageState::record(std::uint64_t h, int symbol, bool negative) {
  signedSymbol_[static_cast<std::size_t>(h - begin_)] = static_cast<std::int8_t>(negative ? -symbol : symbol);
}

void encodeContextValue(RangeEncoder& out, ContextPageState& state, std::uint64_t h, const ContextPoint& point,
                        std::int32_t value) {
  const ContextResidual r =
      codeContextResidual(EncodeBits{out}, state.models(), point.contexts, point.prediction, value);
  state.record(h, r.symbol, r.negative);
}

ContextPageInput::ContextPageInput(std::string_view bytes, std::size_t streamOffset, std::string what)
    : in_(bytes), pageBytes_(bytes.size()), streamOffset_(streamOffset), what_(std::move(what)) {
  if (bytes.size() < 5 || !in_.firstByteValid())  // named at the page's first byte
    throw StreamError(streamOffset_, what_ + ": " +
                                         (bytes.size() < 5 ? "a page of the context coder has at least 5 bytes"
                                                           : "the first byte of a context page must be 0"));
}

void ContextPageInput::checkInside(std::uint64_t value) const {
  if (in_.overrun()) fail("the page ends inside value " + std::to_string(value));
}

void ContextPageInput::finish(std::uint64_t values) const {
  if (values == 0) fail("the page holds no point of the volume (a stream stores exactly the pages that do)");
  if (in_.consumed() != pageBytes_)
    fail(std::to_string(pageBytes_ - std::min(in_.consumed(), pageBytes_)) + " bytes left after the last value");
}

void ContextPageInput::fail(const std::string& detail) const {
  throw StreamError(streamOffset_ + std::min(in_.consumed(), pageBytes_), what_ + ": " + detail);
}

ContextPageReader::ContextPageReader(std::string_view bytes, int valueBits, int pageBits, std::uint64_t page,
                                     std::size_t streamOffset, std::string what)
    : state_(valueBits, pageBits, page), input_(bytes, streamOffset, std::move(what)), pageBits_(pageBits) {}

std::int32_t ContextPageReader::next(std::uint64_t h, const ContextPoint& point) {
  const ContextResidual r =
      codeContextResidual(DecodeBits{input_.decoder()}, state_.models(), point.contexts, point.prediction, 0);
  input_.checkInside(read_);
  const int b = state_.models().valueBits();
  if (!r.inRange(b))
    input_.fail("value " + std::to_string(read_) + ": residual magnitude " + std::to_string(r.magnitude) +
                (r.negative ? "" : " (+)") + " is outside the " + std::to_string(b) + "-bit range");
  state_.record(h, r.symbol, r.negative);
  ++read_;
  return r.value;
}

}  // namespace voxref::ref
