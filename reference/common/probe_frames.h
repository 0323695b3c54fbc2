// The probe frames of `voxref probe` (docs/probe.md): what each frame draws, as plain data shared
// by gpu/ (which draws them, gpu/probe_gl.h), emulation/ (which computes what a precision profile
// gives for them, emulation/probe_emu.h) and conformance/ (which infers a driver's arithmetic from
// the read-back bits, conformance/framework/probe/driver_fingerprint.h).
//
// Two kinds of frame, each a full-screen pass (or two) into a small RGBA target:
//   sweep  texture(tex, (u_k, 0.5, 0.5)) of a LINEAR texture `texels` wide and one texel high and
//          deep, u_k = uOrigin + k * uStep for pixel k = x + width * y (row 0 at the bottom),
//          written unblended to an RGBA32F target. uStep is a power of two and every u_k is a
//          float32, so the shader computes u_k exactly.
//   write  every pixel writes the RGBA value its pass gives it (texelFetch of an RGBA32F texture:
//          exact), blended into a cleared (0, 0, 0, 0) target of `format`.
// Every value is deterministic; the same inputs every run, on every machine.
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "reference/common/gl_state.h"

namespace voxref::ref {

struct ProbeSweep {
  std::string_view id;
  bool unorm8 = false;  // RGBA8 texture (codes), else RGBA32F (float bits)
  Wrap wrap = Wrap::ClampToEdge;
  int texels = 2;
  std::vector<std::array<std::uint32_t, 4>> texelCodes;  // RGBA per texel along x
  float uOrigin = 0.0f, uStep = 0.0f;
  int width = 0, height = 0;                                                // RGBA32F target; one sample per pixel
  float u(int k) const { return uOrigin + static_cast<float>(k) * uStep; }  // exact (see above)
};

enum class ProbeBlend {
  OneOne,    // glBlendFunc(GL_ONE, GL_ONE), GL_FUNC_ADD
  SrcAlpha,  // glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), GL_FUNC_ADD
};

struct ProbeWrite {
  std::string_view id;
  FramebufferFormat format = FramebufferFormat::RGBA8;
  ProbeBlend blend = ProbeBlend::OneOne;
  int width = 0, height = 0;
  std::vector<std::vector<std::array<float, 4>>> passes;  // per pass, per pixel x + width * y
};

// What a target holds after a frame: per pixel x + width * y, the RGBA stored codes (unorm codes,
// or float32 bits for RGBA32F), exactly as glReadPixels returns them in the format's own type.
struct ProbeFrame {
  std::string_view id;
  FramebufferFormat format = FramebufferFormat::RGBA32F;
  int width = 0, height = 0;
  std::vector<std::array<std::uint32_t, 4>> codes;
  bool operator==(const ProbeFrame&) const = default;
};

struct ProbeDesign {
  // "sweep.rgba8"   RGBA8, CLAMP_TO_EDGE, 2 texels (0,255,10,200) -> (255,0,201,3), u from 0.25 in
  //                 steps of 2^-15: 2^14 samples per texel (sample k at k * 2^-14 texel past the
  //                 first texel centre; sample 2^14 on the second centre).
  // "sweep.rgba32f" RGBA32F, CLAMP_TO_EDGE, 2 texels, the same u: red 0 -> 1 (the weight itself),
  //                 green and alpha pairs whose fused and unfused lerps differ, blue two denormals.
  // "sweep.repeat_npot" RGBA32F, REPEAT, 3 texels, red 0, 1, 0, u from 7.25 in steps of 2^-21
  //                 (the float spacing at 7.25): the weight where u * 3 and fract(u) * 3 round
  //                 differently.
  std::vector<ProbeSweep> sweeps;
  // "store.rgba8", "store.rgba16"   one ONE/ONE pass of values at and beside every x with
  //                 fl(x (2^b - 1)) = k + 1/2 (half-way between two codes)
  // "requantize.rgba8"  two ONE/ONE passes of the same x = fl((k + f) / 255), f in 0.2 .. 0.8
  // "blend.rgba8"   pass 1 writes (d, 1), pass 2 (s, a) with SRC_ALPHA / ONE_MINUS_SRC_ALPHA; every
  //                 value a unorm8 float k * fl(1/255); red covers all 65536 (s, a) pairs
  std::vector<ProbeWrite> writes;
  static constexpr int kSamplesPerTexel = 1 << 14;  // sweeps: samples from one texel centre to the next
};

// The design above (built once; the same object every call).
const ProbeDesign& probeDesign();

}  // namespace voxref::ref
