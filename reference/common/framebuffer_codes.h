// What a sequence of framebuffer read-backs holds: the red channel's stored codes, plane after
// plane, exactly as GL returned them (or the emulation computed them). The exact oracle compares
// these codes bit for bit; shading turns them into values.
#pragma once

#include <cstdint>
#include <vector>

#include "reference/common/gl_state.h"
#include "reference/common/plane_shading.h"

namespace voxref::ref {

struct CodePlanes {
  FramebufferFormat format = FramebufferFormat::RGBA8;
  int width = 0, height = 0, planes = 0;
  std::vector<std::uint32_t> codes;  // i + width * (j + height * k)
};

// The exact value a stored code stands for: unorm k / (2^b - 1) (correctly rounded to double),
// binary16 and binary32 bits exactly.
double decodeFramebufferCode(FramebufferFormat format, std::uint32_t code);

// Sample values scale * decode(code) (the paper multiplies the read-back plane by n+).
SampleStack toSampleStack(const CodePlanes& planes, double scale);

}  // namespace voxref::ref
