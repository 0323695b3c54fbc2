// Effect pruning is only a saving (issue 7): the emulators with every skipped stage forced on
// (forceAllEffects) give the same bits as with only the stages the scene calls for, on states
// where pruning removes stages (NEAREST: no weight stage; float framebuffers: no clamp, no per-pass
// store) and on states where it removes none.
#include <cstring>

#include <gtest/gtest.h>

#include "emulation/combination_emu.h"
#include "emulation/timevarying_emu.h"
#include "reference/common/fields.h"
#include "reference/sparsegrid/combination.h"
#include "reference/timevarying/plume.h"

namespace voxref::emu {
namespace {

TEST(ForceAllEffects, CombinationSameBitsAsPruned) {
  const ref::Combination c(ref::SparseGrid::fromField({4, true}, ref::analyticField("gaussian_blobs")));
  const ref::PlaneFrame frame = ref::orbitFrame(30, 20, 24, 20, 12);
  struct State {
    ref::TexelFormat texels;
    ref::TextureSizing sizing;
    ref::Filter filter;
    ref::Wrap wrap;
    ref::FramebufferFormat fb;
    bool flush;
  };
  const State states[] = {
      {ref::TexelFormat::R32F, ref::TextureSizing::Padded, ref::Filter::Nearest, ref::Wrap::ClampToEdge,
       ref::FramebufferFormat::RGBA32F, false},
      {ref::TexelFormat::R16, ref::TextureSizing::Exact, ref::Filter::Nearest, ref::Wrap::ClampToBorder,
       ref::FramebufferFormat::RGBA16F, false},
      {ref::TexelFormat::R8, ref::TextureSizing::Padded, ref::Filter::Nearest, ref::Wrap::Repeat,
       ref::FramebufferFormat::RGBA8, false},
      {ref::TexelFormat::R16F, ref::TextureSizing::Exact, ref::Filter::Linear, ref::Wrap::ClampToEdge,
       ref::FramebufferFormat::RGBA32F, false},
      {ref::TexelFormat::R32F, ref::TextureSizing::Padded, ref::Filter::Linear, ref::Wrap::ClampToEdge,
       ref::FramebufferFormat::RGBA32F, true},
      {ref::TexelFormat::R16, ref::TextureSizing::Padded, ref::Filter::Linear, ref::Wrap::ClampToEdge,
       ref::FramebufferFormat::RGBA16, false},
      {ref::TexelFormat::R8, ref::TextureSizing::Padded, ref::Filter::Linear, ref::Wrap::Repeat,
       ref::FramebufferFormat::RGBA12, false},
  };
  int compared = 0;
  for (const char* profileName : {"llvmpipe", "softpipe"})
    for (const State& s : states) {
      const auto textures = ref::buildCombinationTextures(c, {s.texels, s.sizing, ref::ScalingPolicy::Scaled});
      const ref::SamplerState sampler{s.filter, s.wrap, 0.25};
      const PrecisionProfile& profile = *findProfile(profileName);
      const auto pruned = emulateCombination(textures, frame, sampler, s.fb, profile, {s.flush, 2, false});
      const auto forced = emulateCombination(textures, frame, sampler, s.fb, profile, {s.flush, 2, true});
      SCOPED_TRACE(std::string(profileName) + " " + std::string(ref::name(s.texels)) + " " +
                   std::string(ref::name(s.filter)) + " " + std::string(ref::name(s.fb)));
      ASSERT_EQ(forced.planes.codes, pruned.planes.codes);
      ASSERT_EQ(forced.unmodelled, pruned.unmodelled);
      ++compared;
    }
  EXPECT_EQ(compared, 14);
}

TEST(ForceAllEffects, TimeVaryingSameBitsAsPruned) {
  const ref::TimeSeries series = ref::driftingBlobs(32, 2);
  const ref::TransferFunction tf = ref::transferFunction("gray");
  const ref::PlaneFrame frame = ref::orbitFrame(30, 20, 20, 20, 16);
  int compared = 0;
  for (const char* profileName : {"llvmpipe", "softpipe"})
    for (ref::IndexEncoding enc : {ref::IndexEncoding::NormalizedRgba8, ref::IndexEncoding::NormalizedRgba16,
                                   ref::IndexEncoding::NormalizedFloat, ref::IndexEncoding::BlockRgba8}) {
      const ref::TimeVaryingTextures tex = ref::encodeTimeVarying(series, tf, {3, enc});
      for (ref::DecoderVariant v : {ref::DecoderVariant::Literal, ref::DecoderVariant::Paper,
                                    ref::DecoderVariant::TexelCentre, ref::DecoderVariant::TexelFetch}) {
        if (!ref::decoderIncompatibility(v, tex.layout, tex.index.encoding).empty()) continue;
        const PrecisionProfile& profile = *findProfile(profileName);
        SCOPED_TRACE(std::string(profileName) + " encoding " + std::to_string(static_cast<int>(enc)) + " variant " +
                     std::to_string(static_cast<int>(v)));
        const EmulatedDecode pruned = emulateDecodePlanes(tex, v, 1, frame, profile, 2, false);
        const EmulatedDecode forced = emulateDecodePlanes(tex, v, 1, frame, profile, 2, true);
        ASSERT_EQ(forced.colours.colours, pruned.colours.colours);
        for (std::size_t i = 0; i < pruned.samples.size(); ++i)
          ASSERT_EQ(std::memcmp(forced.samples[i].value.data(), pruned.samples[i].value.data(), sizeof(float) * 4), 0)
              << "sample " << i;
        EXPECT_EQ(emulateComposite(tex, v, 1, frame, profile, 2, false, true).colours,
                  emulateComposite(tex, v, 1, frame, profile, 2, false, false).colours);
        ++compared;
      }
    }
  EXPECT_GE(compared, 8);
}

}  // namespace
}  // namespace voxref::emu
