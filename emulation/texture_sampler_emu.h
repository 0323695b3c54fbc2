// texture(sampler3D, u).r as a GL implementation computes it, under a precision profile.
//
// Bit-exact against Mesa 22.3.6 for the profiles of profile.h (float32 as the drivers compute
// it). Paths, chosen once per texture from its format, filter, wraps and the profile:
//   Aos8Linear   llvmpipe's 8-bit fixed-point path (lp_bld_sample_aos.c): unorm8 formats with
//                REPEAT / CLAMP_TO_EDGE, LINEAR. s' = RNE(fl(s * 256 N)) - 128, i0 = s' >> 8,
//                w = s' & 255; lerp8(w, a, b) = a + floor((w (b - a) + 128) / 256) per stage.
//   FloatLinear  float weights: llvmpipe SoA (lp_bld_sample_soa.c) or softpipe (sp_tex_sample.c)
//                formulas; lerps a + w (b - a) fused or not (profile).
//   Nearest      floor(fl(s N)) wrapped, both families.
// Trilinear order (both drivers): x on the four edges (y0 z0, y1 z0, y0 z1, y1 z1), then y, then z.
// Texel values: unorm k * fl(1/(2^b - 1)), binary16 exact, binary32 as stored.
// Safe on any coordinate, including NaN and values far outside [0, 1].
#pragma once

#include <cstdint>
#include <vector>

#include "emulation/effects.h"
#include "emulation/profile.h"
#include "reference/common/gl_state.h"
#include "reference/common/volume.h"

namespace voxref::emu {

enum class SamplerPath { Aos8Linear, FloatLinear, Nearest };

// The texel index NEAREST selects along an axis of n texels for coordinate s (before the border
// test: -1 or n mean "outside" for CLAMP_TO_BORDER). NaN selects texel 0 on both drivers with
// CLAMP_TO_EDGE; +-infinity gives 0 on llvmpipe (the float-to-int conversion yields INT_MIN) and
// 0 / n - 1 on softpipe (measured, research note 2).
int nearestTexelIndex(float s, int n, ref::Wrap wrap, const PrecisionProfile& profile);

class TextureSamplerEmu {
 public:
  // `codes` (red-channel codes, texel_format.h) must outlive the sampler and hold dims' texels.
  // forceAllEffects: run the stages the state does not call for anyway, as identities (pruning
  // measured, issue 7): NEAREST computes the LINEAR path's float weights and runs the seven
  // trilinear lerps with every tap on the selected texel (weightStageIdentity). Same bits.
  TextureSamplerEmu(const ref::Dims3& dims, ref::TexelFormat format, const std::vector<std::uint32_t>& codes,
                    const ref::SamplerState& sampler, const PrecisionProfile& profile, bool forceAllEffects = false);

  // `unmodelled` (optional) is set when the value depends on state the model does not hold
  // (softpipe tile-cache aliasing onto a partly filled tile: stale data of earlier fragments);
  // the returned value is then NaN.
  float sampleRed(float s, float t, float r, bool* unmodelled = nullptr) const;
  SamplerPath path() const { return path_; }
  // The float weight stage run on a value that needs none (forceAllEffects): the weights of
  // (s, t, r) as the float LINEAR path computes them (this sampler's wrap and profile), then the
  // seven lerps of a trilinear lookup whose eight taps all hold `value`. b - a = 0, so the result
  // is `value` bit for bit (non-finite values and weights are passed through unchanged).
  float weightStageIdentity(float value, float s, float t, float r) const;
  // The effects this texture's sampling simulates (storage, conversion, weights, lerps, border).
  std::vector<Effect> effects() const;

 private:
  struct FloatAxis {
    int i0, i1;
    float w;
  };
  struct FixedAxis {
    int i0, i1, w;
  };
  FloatAxis floatLinearAxis(float s, int n) const;
  FixedAxis aosLinearAxis(float s, int n) const;
  float texel(int x, int y, int z) const;               // value, or border when out of range
  std::uint32_t texelCode8(int x, int y, int z) const;  // AoS: the stored byte
  float lerp(float w, float a, float b) const;
  // The eight taps of a softpipe trilinear lookup after its tile-cache aliasing (profile.h).
  void aliasTaps(const int x[2], const int y[2], const int z[2], float values[8], bool* unmodelled) const;

  ref::Dims3 dims_;
  ref::TexelFormat format_;
  const std::vector<std::uint32_t>* codes_;
  ref::SamplerState sampler_;
  const PrecisionProfile* profile_;
  SamplerPath path_;
  float border_;
  bool force_ = false;
};

}  // namespace voxref::emu
