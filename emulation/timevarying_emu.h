// The time-varying decoders (reference/timevarying/decoder_variants.h) as a driver runs them,
// under a precision profile: the shaders' float32 arithmetic (gpu/shaders/timevarying_*.frag),
// NEAREST texel selection, unorm texel conversion, the RGBA8 output, and for composited frames
// the SRC_ALPHA / ONE_MINUS_SRC_ALPHA blend of the slices (framebuffer_emu.h).
//
// Bit-exact: the colours the GL path reads back, on the implementation the profile describes.
// Besides colours, the emulation reports which index and refinement texels each sample fetched,
// so that conformance can count fetches of a wrong voxel or block. Deterministic for every
// thread count.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "emulation/effects.h"
#include "emulation/profile.h"
#include "emulation/texture_sampler_emu.h"
#include "reference/common/plane_frame.h"
#include "reference/common/rgba.h"
#include "reference/timevarying/address_textures.h"
#include "reference/timevarying/decoder_variants.h"

namespace voxref::emu {

// What the emulated decoder fetched (as gpu::measureFetchesGl measures it on GL) and wrote.
struct DecodedSample : ref::TexelFetch {
  std::array<float, 4> value{};  // the fragment colour the shader writes
};

class TimeVaryingDecoderEmu {
 public:
  // Throws std::invalid_argument when the decoder cannot read these textures.
  // forceAllEffects: run the stages the decoder skips anyway, as identities (issue 7: pruning
  // measured): every NEAREST fetch (and texelFetch) goes through the LINEAR path's float weight
  // stage, the seven trilinear lerps of each channel with every tap on the fetched texel
  // (TextureSamplerEmu::weightStageIdentity). Same bits; only the time differs.
  TimeVaryingDecoderEmu(const ref::TimeVaryingTextures& textures, ref::DecoderVariant variant,
                        const PrecisionProfile& profile, bool forceAllEffects = false);
  DecodedSample decode(int step, glm::vec3 p) const;  // p exactly as the shader's samplePoint()
  std::vector<Effect> effects() const;

 private:
  std::array<float, 4> indexTexel(const std::array<int, 3>& t) const;
  std::array<float, 4> refinementTexel(const std::array<int, 3>& t) const;
  std::array<int, 3> nearest(const ref::Dims3& dims, float s, float t, float r) const;

  const ref::TimeVaryingTextures* tex_;
  ref::DecoderVariant variant_;
  const PrecisionProfile* profile_;
  bool force_ = false;
  std::vector<std::uint32_t> noCodes_;                                 // the weight stage reads no texel
  std::optional<TextureSamplerEmu> indexWeights_, refinementWeights_;  // forced weight stages
  std::array<float, 4> forcedWeights(const std::optional<TextureSamplerEmu>& w, std::array<float, 4> v,
                                     const float c[3]) const;
};

struct EmulatedDecode {
  ref::RgbaStack colours;              // RGBA8 read-back of every plane (0 where discarded)
  std::vector<DecodedSample> samples;  // per sample, same order
};

// The fetches alone, in the same order.
std::vector<ref::TexelFetch> fetchesOf(const EmulatedDecode& decoded);

// Every plane decoded separately (no blending), as gpu::decodePlanesGl.
EmulatedDecode emulateDecodePlanes(const ref::TimeVaryingTextures& textures, ref::DecoderVariant variant, int step,
                                   const ref::PlaneFrame& frame, const PrecisionProfile& profile, int threads = 0,
                                   bool forceAllEffects = false);

// The planes composited back to front, as gpu::compositeGl: one image.
ref::RgbaStack emulateComposite(const ref::TimeVaryingTextures& textures, ref::DecoderVariant variant, int step,
                                const ref::PlaneFrame& frame, const PrecisionProfile& profile, int threads = 0,
                                bool flushEachPass = false, bool forceAllEffects = false);

}  // namespace voxref::emu
