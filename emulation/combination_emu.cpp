#include "emulation/combination_emu.h"

#include <algorithm>
#include <cmath>

#include "emulation/framebuffer_emu.h"
#include "emulation/texture_sampler_emu.h"
#include "reference/common/parallel.h"
#include "reference/common/rounding.h"

namespace voxref::emu {

float combinationTexCoord(float p, int level, int extent, int origin) {
  const float node = p * static_cast<float>(ref::powerOfTwo(level));  // exact: a power-of-two scale
  const float centred = node + 0.5f;                                  // exact on the plane-frame lattice
  const float local = centred - static_cast<float>(origin);           // exact: an integer below 2^13
  return local / static_cast<float>(extent);                          // the one rounding of the address
}

std::vector<Effect> combinationEffects(const ref::CombinationTextures& textures, const ref::SamplerState& sampler,
                                       ref::FramebufferFormat format, const PrecisionProfile& profile,
                                       const CombinationEmuOptions& options, int width, int height) {
  std::vector<Effect> effects;
  auto add = [&](Effect e) {
    if (std::find(effects.begin(), effects.end(), e) == effects.end()) effects.push_back(e);
  };
  const bool divisionRounds =
      std::any_of(textures.textures.begin(), textures.textures.end(), [](const ref::GridTexture& t) {
        return std::any_of(t.dims.begin(), t.dims.end(), [](int d) { return (d & (d - 1)) != 0; });
      });
  if (divisionRounds) add(Effect::AddressDivision);
  if (ref::brickedGridCount(textures) > 0) add(Effect::TextureBricks);
  for (const ref::GridTexture& t : textures.textures)
    for (Effect e : TextureSamplerEmu(t.dims, textures.format, t.codes, sampler, profile).effects()) add(e);
  for (Effect e : BlendEmu(format, profile, options.flushEachPass, width, height).effects()) add(e);
  return effects;
}

EmulatedPlanes emulateCombination(const ref::CombinationTextures& textures, const ref::PlaneFrame& frame,
                                  const ref::SamplerState& sampler, ref::FramebufferFormat format,
                                  const PrecisionProfile& profile, const CombinationEmuOptions& options,
                                  const std::function<void(int)>& progress) {
  const BlendEmu blend(format, profile, options.flushEachPass, frame.width, frame.height, options.forceAllEffects);
  std::vector<TextureSamplerEmu> samplers;
  samplers.reserve(textures.textures.size());
  for (const ref::GridTexture& t : textures.textures)
    samplers.emplace_back(t.dims, textures.format, t.codes, sampler, profile, options.forceAllEffects);

  const std::size_t samples = static_cast<std::size_t>(frame.width) * frame.height * frame.planes;
  EmulatedPlanes out{{format, frame.width, frame.height, frame.planes, std::vector<std::uint32_t>(samples)},
                     std::vector<std::uint8_t>(samples, 0),
                     0};
  // Uniforms exactly as the GL path sets them (exact float32 values, plane_frame.h).
  const glm::vec3 dx(frame.dx), dy(frame.dy);

  auto renderPlane = [&](int k) {
    const glm::vec3 o(frame.planeOrigin(k));
    const std::size_t planeOffset = static_cast<std::size_t>(k) * frame.width * frame.height;
    std::uint32_t* plane = out.planes.codes.data() + planeOffset;
    for (int j = 0; j < frame.height; ++j)
      for (int i = 0; i < frame.width; ++i) {
        const float fx = static_cast<float>(i) + 0.5f, fy = static_cast<float>(j) + 0.5f;  // gl_FragCoord
        // precise vec3 p = planeOrigin + gl_FragCoord.x * pixelDx + gl_FragCoord.y * pixelDy;
        const glm::vec3 p((o.x + fx * dx.x) + fy * dy.x, (o.y + fx * dx.y) + fy * dy.y, (o.z + fx * dx.z) + fy * dy.z);
        PixelState px = blend.cleared();
        bool unmodelled = false;
        const bool discarded = p.x < 0.0f || p.y < 0.0f || p.z < 0.0f || p.x > 1.0f || p.y > 1.0f || p.z > 1.0f;
        if (!discarded)
          for (const ref::CombinationPass& pass : textures.passes) {
            const ref::GridTexture& t = textures.textures[pass.texture];
            // The brick's discard test on c = p * 2^l (exact), as the shader does it.
            if (!ref::servesCell(t, p.x * static_cast<float>(ref::powerOfTwo(t.levels[0])),
                                 p.y * static_cast<float>(ref::powerOfTwo(t.levels[1])),
                                 p.z * static_cast<float>(ref::powerOfTwo(t.levels[2]))))
              continue;
            const float src = samplers[pass.texture].sampleRed(
                combinationTexCoord(p.x, t.levels[0], t.dims[0], t.origin[0]),
                combinationTexCoord(p.y, t.levels[1], t.dims[1], t.origin[1]),
                combinationTexCoord(p.z, t.levels[2], t.dims[2], t.origin[2]), &unmodelled);
            blend.blend(px, src, pass.equation);
          }
        const std::size_t idx = static_cast<std::size_t>(i) + static_cast<std::size_t>(frame.width) * j;
        plane[idx] = blend.resolve(px);
        out.unmodelled[planeOffset + idx] = unmodelled ? 1 : 0;
      }
  };

  ref::parallelFor(frame.planes, options.threads, renderPlane, progress);
  for (std::uint8_t u : out.unmodelled) out.unmodelledCount += u;
  return out;
}

}  // namespace voxref::emu
