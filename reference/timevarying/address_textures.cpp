#include "reference/timevarying/address_textures.h"

#include <bit>
#include <stdexcept>
#include <string>

namespace voxref::ref {
namespace {

void requireAddressable(const Dims3& dims, const char* what) {
  for (int a = 0; a < 3; ++a)
    if (dims[a] < 1 || dims[a] > kMaxAddressableExtent)
      throw std::length_error(std::string("the ") + what + " texture is " + std::to_string(dims[0]) + "x" +
                              std::to_string(dims[1]) + "x" + std::to_string(dims[2]) +
                              ": address textures name texels up to " + std::to_string(kMaxAddressableExtent) +
                              " per axis");
}

// Texel (i, j, k) of `dims`, x fastest: the order of every texture's texels.
template <class F>
void forEachTexel(const Dims3& dims, F&& f) {
  std::size_t n = 0;
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i, ++n) f(n, std::array<int, 3>{i, j, k});
}

std::size_t texelIndex(const Dims3& dims, const std::array<int, 3>& t) {
  return static_cast<std::size_t>(t[0]) +
         static_cast<std::size_t>(dims[0]) * (t[1] + static_cast<std::size_t>(dims[1]) * t[2]);
}

// A texel of a texture of `dims`, or kNoTexel.
bool namesTexelOf(const std::array<int, 3>& t, const Dims3& dims) {
  return t == kNoTexel || (t[0] < dims[0] && t[1] < dims[1] && t[2] < dims[2]);
}

}  // namespace

Rgba8 addressCode(const std::array<int, 3>& t) {
  return {static_cast<std::uint8_t>(t[0] & 255), static_cast<std::uint8_t>(t[1] & 255),
          static_cast<std::uint8_t>(t[2] & 255),
          static_cast<std::uint8_t>(64 + (t[0] >> 8) + 4 * (t[1] >> 8) + 16 * (t[2] >> 8))};
}

std::optional<std::array<int, 3>> texelOfAddressCode(const Rgba8& c) {
  if (c == Rgba8{0, 0, 0, 0}) return kNoTexel;
  if (c[3] < 64 || c[3] > 127) return std::nullopt;
  const int high = c[3] - 64;
  return std::array<int, 3>{c[0] + 256 * (high & 3), c[1] + 256 * ((high >> 2) & 3), c[2] + 256 * (high >> 4)};
}

IndexTexture addressIndexTexture(const IndexTexture& index) {
  requireAddressable(index.dims, "index");
  IndexTexture out{index.encoding, index.dims, std::vector<std::uint32_t>(index.texels.size())};
  forEachTexel(index.dims, [&](std::size_t n, const std::array<int, 3>& t) {
    const Rgba8 code = addressCode(t);
    for (int ch = 0; ch < 4; ++ch) switch (index.encoding) {
        case IndexEncoding::NormalizedRgba16:
          out.texels[4 * n + ch] = 257u * code[ch];  // code / 255 exactly, as the index stores colours
          break;
        case IndexEncoding::NormalizedFloat:
          out.texels[4 * n + ch] = std::bit_cast<std::uint32_t>(static_cast<float>(code[ch]) / 255.0f);
          break;
        default:
          out.texels[4 * n + ch] = code[ch];
      }
  });
  return out;
}

RefinementTexture addressRefinementTexture(const RefinementTexture& refinement) {
  requireAddressable(refinement.dims, "refinement");
  RefinementTexture out{refinement.dims, std::vector<std::uint8_t>(refinement.texels.size())};
  forEachTexel(refinement.dims, [&](std::size_t n, const std::array<int, 3>& t) {
    const Rgba8 code = addressCode(t);
    for (int ch = 0; ch < 4; ++ch) out.texels[4 * n + ch] = code[ch];
  });
  return out;
}

MeasuredFetches fetchesFromAddressPasses(const TimeVaryingTextures& tex, const PlaneFrame& frame,
                                         const RgbaStack& indexPass, const RgbaStack& refinementPass) {
  const std::size_t samples = static_cast<std::size_t>(frame.width) * frame.height * frame.planes;
  if (indexPass.colours.size() != samples || refinementPass.colours.size() != samples)
    throw std::invalid_argument("address passes of " + std::to_string(indexPass.colours.size()) + " and " +
                                std::to_string(refinementPass.colours.size()) + " colours for a frame of " +
                                std::to_string(samples) + " samples");
  MeasuredFetches m;
  m.fetches.resize(samples);
  std::size_t n = 0;
  for (int k = 0; k < frame.planes; ++k)
    for (int j = 0; j < frame.height; ++j)
      for (int i = 0; i < frame.width; ++i, ++n) {
        TexelFetch& f = m.fetches[n];
        const glm::dvec3 p = frame.sample(i, j, k);  // the shader's samplePoint(), exactly (plane_frame.h)
        f.discarded = p.x < 0.0 || p.y < 0.0 || p.z < 0.0 || p.x > 1.0 || p.y > 1.0 || p.z > 1.0;
        if (f.discarded) continue;
        const auto index = texelOfAddressCode(indexPass.colours[n]);
        if (!index || !namesTexelOf(*index, tex.index.dims)) {
          ++m.unreadable, f.discarded = true;
          continue;
        }
        f.indexTexel = *index;
        f.refined = *index != kNoTexel &&
                    isRefinementFlag(tex.index.encoding, &tex.index.texels[4 * texelIndex(tex.index.dims, *index)]);
        if (!f.refined) continue;
        const auto refinement = texelOfAddressCode(refinementPass.colours[n]);
        if (!refinement || !namesTexelOf(*refinement, tex.refinement.dims)) {
          ++m.unreadable, f.discarded = true;
          continue;
        }
        f.refinementTexel = *refinement;
      }
  return m;
}

Rgba8 colourOfFetch(const TimeVaryingTextures& tex, const TexelFetch& f) {
  if ((f.refined ? f.refinementTexel : f.indexTexel) == kNoTexel) return {0, 0, 0, 0};
  if (!f.refined)
    return colourOfIndexTexel(tex.index.encoding, &tex.index.texels[4 * texelIndex(tex.index.dims, f.indexTexel)]);
  const std::uint8_t* c = &tex.refinement.texels[4 * texelIndex(tex.refinement.dims, f.refinementTexel)];
  return {c[0], c[1], c[2], c[3]};
}

}  // namespace voxref::ref
