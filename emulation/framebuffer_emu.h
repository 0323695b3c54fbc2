// One framebuffer pixel under blending with factors ONE / ONE, as a GL implementation stores and
// blends it, under a precision profile. Bit-exact against Mesa 22.3.6 (docs/precision.md):
//
// QuantizePerPass (llvmpipe; the GL semantics of a fixed-point colour buffer):
//   unorm b bits   src code = clamp(RNE(fl(x (2^b - 1)))), then saturating integer
//                  dst + src (FUNC_ADD) or max(dst - src, 0) (FUNC_REVERSE_SUBTRACT)
//   RGBA16F        fl(src + half(dst)) / fl(half(dst) - src), stored as binary16 toward zero
//   RGBA32F        fl(src + dst) / fl(dst - src), no clamp (FTZ/DAZ when the profile flushes)
// FloatTileCache (softpipe, sp_quad_blend.c + sp_tile_cache.c):
//   float32 tile value; for unorm targets src and the result are clamped to [0, 1] every pass;
//   the stored format is written once, when the tile is flushed (read-back): unorm8 RNE,
//   unorm16 round half up, RGBA16F toward zero. With flush-each-pass the tile is stored and
//   reloaded (k * fl(1/(2^b - 1))) after every pass.
// RGBA12 exists only here: a 12-bit fixed-point buffer with the QuantizePerPass semantics, the
// precision of the 1999 paper's hardware; no GL implementation runs it.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "emulation/effects.h"
#include "emulation/profile.h"
#include "reference/common/gl_state.h"

namespace voxref::emu {

struct PixelState {
  std::uint32_t code = 0;  // stored code (QuantizePerPass)
  float value = 0.0f;      // tile value (FloatTileCache)
};

class BlendEmu {
 public:
  // Throws std::invalid_argument if the profile cannot model a target of this size (softpipe's
  // tile cache evicts, and so quantizes, tiles of targets over 320 x 640).
  // forceAllEffects: run the stages the format does not call for anyway, as identities (pruning
  // measured, issue 7): float formats run the per-pass clamp of source and result with the
  // format's own bounds (-inf, +inf; NaN passes), and a float32 tile is stored and reloaded every
  // pass (a bit cast). Same bits as without.
  BlendEmu(ref::FramebufferFormat format, const PrecisionProfile& profile, bool flushEachPass, int width, int height,
           bool forceAllEffects = false);

  PixelState cleared() const { return {}; }  // glClearColor(0, 0, 0, 0)
  void blend(PixelState& pixel, float src, ref::BlendEquation equation) const;
  std::uint32_t resolve(const PixelState& pixel) const;  // what glReadPixels returns
  std::vector<Effect> effects() const;

 private:
  std::uint32_t store(float value) const;  // tile value -> stored code (FloatTileCache)
  float reload(std::uint32_t code) const;  // stored code -> tile value
  float formatClamp(float x) const;        // forced clamp of a float format: an identity

  ref::FramebufferFormat format_;
  const PrecisionProfile* profile_;
  FramebufferModel model_;
  bool flushEachPass_;
  int bits_;  // unorm bits, 0 for float formats
  bool force_ = false;
  float clampLo_, clampHi_;  // the float formats' range: read at run time, so the forced clamp is run
};

// RGBA8 blending with glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), GL_FUNC_ADD: the
// compositing of view-aligned slices. Bit-exact against Mesa 22.3.6 (research note 2, all 2^24
// (src, alpha, dst) byte combinations checked on both drivers):
//   llvmpipe  s = clamp(RNE(fl(min(x, 1) * 255))) per channel, a = s.alpha;
//             out = min(255, mulnorm(s, a) + mulnorm(d, 255 - a)) with
//             mulnorm(x, y) = (t + (t >> 8) + 128) >> 8, t = x y (lp_bld_arit.c lp_build_mul_norm);
//             stored after every draw
//   softpipe  s = clamp(x, 0, 1), a = s.alpha, oma = fl(1 - a);
//             r = clamp(fl(fl(s * a) + fl(d * oma)), 0, 1) in the float tile; RNE(r * 255) at flush
class AlphaBlendEmu {
 public:
  struct Pixel {
    std::array<std::uint8_t, 4> code{};  // llvmpipe
    std::array<float, 4> value{};        // softpipe tile
  };
  // flushEachPass: glFinish after every slice; a float tile is stored and reloaded (unorm8) each time.
  explicit AlphaBlendEmu(const PrecisionProfile& profile, bool flushEachPass = false)
      : profile_(&profile), flush_(flushEachPass) {}
  Pixel cleared() const { return {}; }  // glClearColor(0, 0, 0, 0)
  void blend(Pixel& pixel, const std::array<float, 4>& src) const;
  std::array<std::uint8_t, 4> resolve(const Pixel& pixel) const;
  std::vector<Effect> effects() const;

 private:
  const PrecisionProfile* profile_;
  bool flush_;
};

// mulnorm(x, y) of llvmpipe: (t + (t >> 8) + 128) >> 8 with t = x y. One below round(x y / 255)
// for 12 products (24 of the 65536 ordered pairs), for example 152 * 229.
std::uint8_t mulnorm8(std::uint8_t x, std::uint8_t y);

}  // namespace voxref::emu
