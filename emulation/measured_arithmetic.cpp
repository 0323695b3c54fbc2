#include "emulation/measured_arithmetic.h"

namespace voxref::emu {

std::string MeasuredArithmetic::describe() const {
  std::string s;
  auto add = [&](const std::string& phrase) { s += (s.empty() ? "" : ", ") + phrase; };
  if (floatFiltering) add("float filtering (sampling.float.subtexel_bits = float, sampling.float.lerp known)");
  if (unorm8Store == Store::Nearest) add("8-bit stores round to nearest (store.unorm8_rounding)");
  if (unorm8Store == Store::Floor) add("8-bit stores round down (store.unorm8_rounding = floor)");
  if (srcAlphaBlend == Blend::Mulnorm) add("SRC_ALPHA blending by Mesa's mulnorm (blend.rgba8_src_alpha)");
  if (srcAlphaBlend == Blend::Exact) add("SRC_ALPHA blending by round(x y / 255) (blend.rgba8_src_alpha)");
  if (requantizedPasses) add("every pass requantized (framebuffer.between_passes = requantized)");
  return s.empty() ? "nothing (the spec's rules)" : s;
}

}  // namespace voxref::emu
