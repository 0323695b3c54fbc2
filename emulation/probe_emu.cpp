#include "emulation/probe_emu.h"

#include <bit>

#include "emulation/framebuffer_emu.h"
#include "emulation/texture_sampler_emu.h"

namespace voxref::emu {
namespace {

ref::ProbeFrame sweepFrame(const ref::ProbeSweep& sweep, const PrecisionProfile& profile) {
  ref::ProbeFrame frame{sweep.id, ref::FramebufferFormat::RGBA32F, sweep.width, sweep.height, {}};
  const ref::SamplerState sampler{ref::Filter::Linear, sweep.wrap, 0.0};
  const ref::TexelFormat format = sweep.unorm8 ? ref::TexelFormat::RGBA8 : ref::TexelFormat::R32F;
  std::vector<std::vector<std::uint32_t>> channelCodes(4);
  for (const auto& texel : sweep.texelCodes)
    for (int c = 0; c < 4; ++c) channelCodes[c].push_back(texel[c]);
  std::vector<TextureSamplerEmu> channels;
  for (int c = 0; c < 4; ++c)
    channels.emplace_back(ref::Dims3{sweep.texels, 1, 1}, format, channelCodes[c], sampler, profile);
  const int samples = sweep.width * sweep.height;
  frame.codes.resize(static_cast<std::size_t>(samples));
  for (int k = 0; k < samples; ++k)
    for (int c = 0; c < 4; ++c)
      frame.codes[k][c] = std::bit_cast<std::uint32_t>(channels[c].sampleRed(sweep.u(k), 0.5f, 0.5f));
  return frame;
}

ref::ProbeFrame writeFrame(const ref::ProbeWrite& write, const PrecisionProfile& profile) {
  ref::ProbeFrame frame{write.id, write.format, write.width, write.height, {}};
  const std::size_t pixels = static_cast<std::size_t>(write.width) * write.height;
  frame.codes.resize(pixels);
  if (write.blend == ref::ProbeBlend::OneOne) {
    const BlendEmu blend(write.format, profile, false, write.width, write.height);
    for (std::size_t i = 0; i < pixels; ++i)
      for (int c = 0; c < 4; ++c) {
        PixelState px = blend.cleared();
        for (const auto& pass : write.passes) blend.blend(px, pass[i][c], ref::BlendEquation::FuncAdd);
        frame.codes[i][c] = blend.resolve(px);
      }
    return frame;
  }
  const AlphaBlendEmu blend(profile);  // RGBA8 only (framebuffer_emu.h)
  for (std::size_t i = 0; i < pixels; ++i) {
    AlphaBlendEmu::Pixel px = blend.cleared();
    for (const auto& pass : write.passes) blend.blend(px, pass[i]);
    const auto rgba = blend.resolve(px);
    for (int c = 0; c < 4; ++c) frame.codes[i][c] = rgba[c];
  }
  return frame;
}

}  // namespace

std::vector<ref::ProbeFrame> emulateProbeFrames(const ref::ProbeDesign& design, const PrecisionProfile& profile) {
  std::vector<ref::ProbeFrame> frames;
  for (const ref::ProbeSweep& s : design.sweeps) frames.push_back(sweepFrame(s, profile));
  for (const ref::ProbeWrite& w : design.writes) frames.push_back(writeFrame(w, profile));
  return frames;
}

}  // namespace voxref::emu
