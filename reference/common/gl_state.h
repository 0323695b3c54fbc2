// The parts of GL state that voxref scenes set, as plain data shared by every layer.
//
// This header names state; it does not call GL. gpu/ maps these values to GL enums, emulation/
// derives the effects they call for, conformance/ parses and prints them. Names follow the GL
// enums in lower case (`clamp_to_edge`, `rgba16f`) so that scene files read like GL code.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace voxref::ref {

// Internal formats of sampled textures. Only the red channel carries data; RGBA8 stores zero
// in green, blue and alpha.
enum class TexelFormat { R8, RGBA8, R16, R16F, R32F };

// Colour attachment formats. RGBA12 does not exist in GL implementations here (Mesa has no
// 12-bit colour buffer): it is emulated only and every report says so.
enum class FramebufferFormat { RGBA8, RGBA12, RGBA16, RGBA16F, RGBA32F };

enum class Filter { Nearest, Linear };
enum class Wrap { ClampToEdge, Repeat, ClampToBorder };
enum class BlendEquation { FuncAdd, FuncReverseSubtract };

struct SamplerState {
  Filter filter = Filter::Linear;
  Wrap wrap = Wrap::ClampToEdge;  // the same on s, t and r
  double borderRed = 0.0;         // used by ClampToBorder only
};

std::string_view name(TexelFormat f);
std::string_view name(FramebufferFormat f);
std::string_view name(Filter f);
std::string_view name(Wrap w);
std::string_view name(BlendEquation e);

// Parsers accept exactly the names above; they return nullopt for anything else.
std::optional<TexelFormat> parseTexelFormat(std::string_view s);
std::optional<FramebufferFormat> parseFramebufferFormat(std::string_view s);
std::optional<Filter> parseFilter(std::string_view s);
std::optional<Wrap> parseWrap(std::string_view s);

// Bits per channel of a unorm framebuffer format, 0 for float formats.
int unormBits(FramebufferFormat f);
// True for formats whose values GL clamps to [0, 1] (the fixed-point ones).
bool clampsToUnitRange(FramebufferFormat f);
// True when a GL implementation can create this format as a colour attachment.
bool existsInGl(FramebufferFormat f);

}  // namespace voxref::ref
