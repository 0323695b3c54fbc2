#include "conformance/modules/timevarying/fetch_classification.h"

#include <algorithm>
#include <cmath>

#include "reference/timevarying/exact_colours.h"

namespace voxref::conf {

void FetchCounts::add(const FetchCounts& o) {
  samples += o.samples;
  right += o.right;
  wrongBlock += o.wrongBlock;
  wrongVoxel += o.wrongVoxel;
  wrongColour += o.wrongColour;
  unexplained += o.unexplained;
  atCoordinateOne += o.atCoordinateOne;
  onBlockFace += o.onBlockFace;
  onVoxelFace += o.onVoxelFace;
  inside += o.inside;
  for (const auto& e : o.examples)
    if (examples.size() < 10) examples.push_back(e);
}

nlohmann::json FetchCounts::toJson() const {
  return {{"samples", samples},
          {"right", right},
          {"wrong_block", wrongBlock},
          {"wrong_voxel", wrongVoxel},
          {"wrong_colour", wrongColour},
          {"unexplained", unexplained},
          {"wrong_by_place",
           {{"coordinate_one", atCoordinateOne},
            {"block_face", onBlockFace},
            {"voxel_face", onVoxelFace},
            {"inside", inside}}},
          {"examples", examples}};
}

FetchCounts classifyFetches(const ref::TimeVaryingTextures& tex, const ref::TimeSeries& input,
                            const ref::TransferFunction& tf, int step, const ref::PlaneFrame& frame,
                            const std::vector<ref::TexelFetch>& fetches, const std::vector<ref::Rgba8>& colours) {
  const ref::TimeVaryingLayout& L = tex.layout;
  FetchCounts c;
  std::size_t idx = 0;
  for (int k = 0; k < frame.planes; ++k)
    for (int j = 0; j < frame.height; ++j)
      for (int i = 0; i < frame.width; ++i, ++idx) {
        const ref::TexelFetch& s = fetches[idx];
        if (s.discarded) continue;
        ++c.samples;
        const glm::dvec3 p = frame.sample(i, j, k);  // exact: the frame's lattice
        std::array<int, 3> v{};
        bool one = false, blockFace = false, voxelFace = false;
        for (int a = 0; a < 3; ++a) {
          const double scaled = p[a] * L.side;
          v[a] = std::min(static_cast<int>(std::floor(scaled)), L.side - 1);
          one |= p[a] == 1.0;
          voxelFace |= scaled == std::floor(scaled);
          blockFace |= scaled == std::floor(scaled) && static_cast<long>(scaled) % L.blockSide == 0;
        }
        if (colours[idx] != ref::inputColour(input, tf, step, p)) ++c.wrongColour;
        ref::VoxelAddress want;
        bool addressable = true;
        try {
          want = ref::addressOfVoxel(tex, step, v[0], v[1], v[2]);
        } catch (const std::out_of_range&) {
          addressable = false;  // a flag whose "address" is a colour: no fetch can be right
        }
        bool wrongBlock = !addressable || s.indexTexel != want.indexTexel || s.refined != want.refined,
             wrongVoxel = false;
        if (!wrongBlock && want.refined) {
          wrongBlock = s.refinementTexel == ref::kNoTexel;
          for (int a = 0; a < 3; ++a)
            wrongBlock |= s.refinementTexel[a] / L.blockSide != want.refinementTexel[a] / L.blockSide;
          wrongVoxel = !wrongBlock && s.refinementTexel != want.refinementTexel;
        }
        if (!wrongBlock && !wrongVoxel) {
          ++c.right;
          continue;
        }
        (wrongBlock ? c.wrongBlock : c.wrongVoxel) += 1;
        (one ? c.atCoordinateOne : blockFace ? c.onBlockFace : voxelFace ? c.onVoxelFace : c.inside) += 1;
        if (c.examples.size() < 10)
          c.examples.push_back(
              {{"step", step},
               {"p", {p.x, p.y, p.z}},
               {"voxel", v},
               {"kind", wrongBlock ? "wrong_block" : "wrong_voxel"},
               {"index_texel", s.indexTexel},
               {"expected_index_texel", want.indexTexel},
               {"refinement_texel", s.refined ? nlohmann::json(s.refinementTexel) : nlohmann::json(nullptr)},
               {"expected_refinement_texel",
                want.refined ? nlohmann::json(want.refinementTexel) : nlohmann::json(nullptr)}});
      }
  return c;
}

std::vector<ref::Rgba8> coloursOfFetches(const ref::TimeVaryingTextures& textures,
                                         const std::vector<ref::TexelFetch>& fetches) {
  std::vector<ref::Rgba8> out(fetches.size(), ref::Rgba8{0, 0, 0, 0});
  for (std::size_t i = 0; i < fetches.size(); ++i)
    if (!fetches[i].discarded) out[i] = ref::colourOfFetch(textures, fetches[i]);
  return out;
}

std::size_t unexplainedColours(const std::vector<ref::Rgba8>& fetched, const std::vector<ref::TexelFetch>& fetches,
                               const std::vector<ref::Rgba8>& gl) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < fetches.size(); ++i) n += !fetches[i].discarded && fetched[i] != gl[i];
  return n;
}

std::size_t differingFetches(const std::vector<ref::TexelFetch>& a, const std::vector<ref::TexelFetch>& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    n += a[i].discarded != b[i].discarded ||
         (!a[i].discarded && (a[i].indexTexel != b[i].indexTexel || a[i].refined != b[i].refined ||
                              (a[i].refined && a[i].refinementTexel != b[i].refinementTexel)));
  return n;
}

}  // namespace voxref::conf
