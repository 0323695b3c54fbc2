#include "reference/leb/adaptive_delta_coder.h"

#include <algorithm>
#include <stdexcept>

#include "reference/common/byte_stream.h"
#include "reference/leb/delta_decisions.h"
#include "reference/leb/lead1_coder.h"

namespace voxref::ref {
namespace {

constexpr int kContextsPerComponent = (kAdaptiveSymbolCap + 1) * (kAdaptiveSymbolCap + 1);

// The value bits, once they and the components are checked (before any model is allocated).
int checkedValueBits(int valueBits, int components) {
  if (valueBits != 8 && valueBits != 16)
    throw std::invalid_argument("adaptive delta coder: value bits must be 8 or 16, got " + std::to_string(valueBits));
  if (components != 1 && components != 3)
    throw std::invalid_argument("adaptive delta coder: components must be 1 or 3, got " + std::to_string(components));
  return valueBits;
}

}  // namespace

AdaptiveDeltaModels::AdaptiveDeltaModels(int valueBits, int components)
    : DeltaDecisionModels(checkedValueBits(valueBits, components), components * kContextsPerComponent, components),
      components_(components) {}

int AdaptiveContext::next() const {
  const int lag = components_ == 1 ? 2 : components_;
  const int component = static_cast<int>(at_ % static_cast<std::size_t>(components_));
  const int previous = history_[(at_ + 3) & 3];
  const int before = history_[(at_ + 4 - static_cast<std::size_t>(lag)) & 3];
  return (component * (kAdaptiveSymbolCap + 1) + previous) * (kAdaptiveSymbolCap + 1) + before;
}

void AdaptiveContext::push(int symbol) {
  history_[at_ & 3] = static_cast<std::uint8_t>(std::min(symbol, kAdaptiveSymbolCap));
  ++at_;
}

std::string encodeAdaptivePage(std::span<const std::int32_t> deltas, int valueBits, int components) {
  AdaptiveDeltaModels models(valueBits, components);
  AdaptiveContext context(components);
  RangeEncoder out;
  const std::int32_t lo = -(1 << (valueBits - 1)), hi = (1 << (valueBits - 1)) - 1;
  for (std::size_t i = 0; i < deltas.size(); ++i) {
    const std::int32_t d = deltas[i];
    if (d < lo || d > hi)
      throw std::invalid_argument("adaptive delta coder: delta " + std::to_string(d) + " is not a " +
                                  std::to_string(valueBits) + "-bit two's complement value");
    int negative = d < 0 ? 1 : 0;
    std::uint32_t magnitude = static_cast<std::uint32_t>(d < 0 ? -static_cast<std::int64_t>(d) : d);
    const int symbol = lead1Symbol(d);
    codeDeltaDecisions(EncodeBits{out}, models, context.next(),
                       static_cast<int>(i % static_cast<std::size_t>(components)), symbol, negative, magnitude);
    context.push(symbol);
  }
  return out.finish();
}

AdaptivePageReader::AdaptivePageReader(std::string_view page, int valueBits, int components, std::size_t streamOffset,
                                       std::string what)
    : models_(valueBits, components),
      context_(components),
      in_(page),
      pageBytes_(page.size()),
      streamOffset_(streamOffset),
      what_(std::move(what)) {
  if (page.size() < 5 || !in_.firstByteValid())
    fail(page.size() < 5 ? "a page of the adaptive coder has at least 5 bytes"
                         : "the first byte of an adaptive page must be 0");
}

std::int32_t AdaptivePageReader::next() {
  const int component = static_cast<int>(read_ % static_cast<std::size_t>(models_.components()));
  int negative = 0;
  std::uint32_t magnitude = 0;
  const int s = codeDeltaDecisions(DecodeBits{in_}, models_, context_.next(), component, 0, negative, magnitude);
  if (in_.overrun()) fail("the page ends inside value " + std::to_string(read_));
  const int b = models_.valueBits();
  if (s == b && (magnitude != (1u << (b - 1)) || !negative))
    fail("value " + std::to_string(read_) + ": magnitude " + std::to_string(magnitude) + (negative ? "" : " (+)") +
         " is outside the " + std::to_string(b) + "-bit range");
  context_.push(s);
  ++read_;
  if (s == 0) return 0;
  return negative ? -static_cast<std::int32_t>(magnitude) : static_cast<std::int32_t>(magnitude);
}

void AdaptivePageReader::finish() const {
  if (in_.consumed() != pageBytes_)
    fail(std::to_string(pageBytes_ - std::min(in_.consumed(), pageBytes_)) + " bytes left after the last value");
}

void AdaptivePageReader::fail(const std::string& detail) const {
  throw StreamError(streamOffset_ + std::min(in_.consumed(), pageBytes_), what_ + ": " + detail);
}

}  // namespace voxref::ref
