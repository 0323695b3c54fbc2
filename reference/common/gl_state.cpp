#include "reference/common/gl_state.h"

#include <array>
#include <utility>

namespace voxref::ref {
namespace {

template <class E, std::size_t N>
std::optional<E> lookup(const std::array<std::pair<E, std::string_view>, N>& table, std::string_view s) {
  for (const auto& [value, text] : table)
    if (text == s) return value;
  return std::nullopt;
}

template <class E, std::size_t N>
std::string_view nameOf(const std::array<std::pair<E, std::string_view>, N>& table, E e) {
  for (const auto& [value, text] : table)
    if (value == e) return text;
  return "?";
}

constexpr std::array<std::pair<TexelFormat, std::string_view>, 5> kTexelFormats{{
    {TexelFormat::R8, "r8"},
    {TexelFormat::RGBA8, "rgba8"},
    {TexelFormat::R16, "r16"},
    {TexelFormat::R16F, "r16f"},
    {TexelFormat::R32F, "r32f"},
}};
constexpr std::array<std::pair<FramebufferFormat, std::string_view>, 5> kFramebufferFormats{{
    {FramebufferFormat::RGBA8, "rgba8"},
    {FramebufferFormat::RGBA12, "rgba12"},
    {FramebufferFormat::RGBA16, "rgba16"},
    {FramebufferFormat::RGBA16F, "rgba16f"},
    {FramebufferFormat::RGBA32F, "rgba32f"},
}};
constexpr std::array<std::pair<Filter, std::string_view>, 2> kFilters{{
    {Filter::Nearest, "nearest"},
    {Filter::Linear, "linear"},
}};
constexpr std::array<std::pair<Wrap, std::string_view>, 3> kWraps{{
    {Wrap::ClampToEdge, "clamp_to_edge"},
    {Wrap::Repeat, "repeat"},
    {Wrap::ClampToBorder, "clamp_to_border"},
}};
constexpr std::array<std::pair<BlendEquation, std::string_view>, 2> kBlendEquations{{
    {BlendEquation::FuncAdd, "func_add"},
    {BlendEquation::FuncReverseSubtract, "func_reverse_subtract"},
}};

}  // namespace

std::string_view name(TexelFormat f) { return nameOf(kTexelFormats, f); }
std::string_view name(FramebufferFormat f) { return nameOf(kFramebufferFormats, f); }
std::string_view name(Filter f) { return nameOf(kFilters, f); }
std::string_view name(Wrap w) { return nameOf(kWraps, w); }
std::string_view name(BlendEquation e) { return nameOf(kBlendEquations, e); }

std::optional<TexelFormat> parseTexelFormat(std::string_view s) { return lookup(kTexelFormats, s); }
std::optional<FramebufferFormat> parseFramebufferFormat(std::string_view s) { return lookup(kFramebufferFormats, s); }
std::optional<Filter> parseFilter(std::string_view s) { return lookup(kFilters, s); }
std::optional<Wrap> parseWrap(std::string_view s) { return lookup(kWraps, s); }

int unormBits(FramebufferFormat f) {
  switch (f) {
    case FramebufferFormat::RGBA8:
      return 8;
    case FramebufferFormat::RGBA12:
      return 12;
    case FramebufferFormat::RGBA16:
      return 16;
    case FramebufferFormat::RGBA16F:
    case FramebufferFormat::RGBA32F:
      return 0;
  }
  return 0;
}

bool clampsToUnitRange(FramebufferFormat f) { return unormBits(f) != 0; }

bool existsInGl(FramebufferFormat f) { return f != FramebufferFormat::RGBA12; }

}  // namespace voxref::ref
