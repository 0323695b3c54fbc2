#include "conformance/modules/sparsegrid/sparsegrid_catalog.h"

#include <string>

#include "conformance/modules/sparsegrid/combination_conf.h"
#include "conformance/modules/sparsegrid/figure9_conf.h"

namespace voxref::conf {
namespace {

using ref::FramebufferFormat;
using ref::RenderMode;
using ref::TexelFormat;

std::string str(std::string_view s) { return std::string(s); }

// An axis-aligned frame whose samples sit at origin + (i, j, k) * step.
void latticeCamera(SparseGridScene& s, glm::dvec3 first, double step, int w, int h, int planes) {
  s.camera.origin = first - glm::dvec3(step / 2);
  s.camera.dx = glm::dvec3(step, 0, 0);
  s.camera.dy = glm::dvec3(0, step, 0);
  s.camera.dz = glm::dvec3(0, 0, step);
  s.width = w;
  s.height = h;
  s.planes = planes;
}

void addMainCases(std::vector<Case>& cases) {
  const RenderMode modes[] = {RenderMode::XRay, RenderMode::Mip, RenderMode::Iso};
  const FramebufferFormat formats[] = {FramebufferFormat::RGBA8, FramebufferFormat::RGBA16, FramebufferFormat::RGBA16F,
                                       FramebufferFormat::RGBA32F, FramebufferFormat::RGBA12};
  for (FramebufferFormat fb : formats)
    for (int level = 3; level <= 8; ++level)
      for (RenderMode mode : modes) {
        SparseGridScene s = defaultSparseGridScene();
        s.grid.level = level;
        s.framebuffer = fb;
        s.shading.mode = mode;
        const std::string id =
            "sparsegrid.combination." + str(ref::name(fb)) + ".l" + std::to_string(level) + "." + str(ref::name(mode));
        std::string what = "combination technique, level " + std::to_string(level) + ", " + str(ref::name(mode)) +
                           ", " + str(ref::name(fb)) + " framebuffer, r16 padded textures";
        if (!ref::existsInGl(fb)) what += " (emulated only: GL has no 12-bit colour buffer)";
        cases.push_back(combinationCase(id, what, s));
      }
}

void addTextureCases(std::vector<Case>& cases) {
  const TexelFormat formats[] = {TexelFormat::R8, TexelFormat::RGBA8, TexelFormat::R16, TexelFormat::R16F,
                                 TexelFormat::R32F};
  for (TexelFormat tf : formats)
    for (ref::TextureSizing sizing : {ref::TextureSizing::Padded, ref::TextureSizing::Exact})
      for (ref::Filter filter : {ref::Filter::Linear, ref::Filter::Nearest})
        for (ref::Wrap wrap : {ref::Wrap::ClampToEdge, ref::Wrap::Repeat, ref::Wrap::ClampToBorder}) {
          SparseGridScene s = defaultSparseGridScene();
          s.grid.level = 5;
          s.textures.format = tf;
          s.textures.sizing = sizing;
          s.sampler = {filter, wrap, wrap == ref::Wrap::ClampToBorder ? 0.25 : 0.0};
          s.framebuffer = FramebufferFormat::RGBA32F;  // no framebuffer rounding: sampling shows whole
          s.shading.mode = RenderMode::Mip;
          const std::string id = "sparsegrid.texture." + str(ref::name(tf)) + "." + str(ref::name(sizing)) + "." +
                                 str(ref::name(filter)) + "." + str(ref::name(wrap));
          cases.push_back(combinationCase(id,
                                          "texture sampling: " + str(ref::name(tf)) + " " + str(ref::name(sizing)) +
                                              " textures, " + str(ref::name(filter)) + ", " + str(ref::name(wrap)) +
                                              ", level 5, rgba32f",
                                          s));
        }
}

void addBrickCases(std::vector<Case>& cases) {
  // Bricks at a small size so that they are tested at every level, not only at 11 and 12.
  for (ref::TextureSizing sizing : {ref::TextureSizing::Padded, ref::TextureSizing::Exact})
    for (FramebufferFormat fb : {FramebufferFormat::RGBA8, FramebufferFormat::RGBA32F}) {
      SparseGridScene s = defaultSparseGridScene();
      s.grid.level = 6;
      s.textures.sizing = sizing;
      s.textures.maxExtent = 16;
      s.framebuffer = fb;
      s.shading.mode = RenderMode::Mip;
      cases.push_back(
          combinationCase("sparsegrid.texture.bricks16." + str(ref::name(sizing)) + "." + str(ref::name(fb)),
                          "grid textures split into 16-texel bricks (" + str(ref::name(sizing)) + ", " +
                              str(ref::name(fb)) + "): per-brick addresses and discards, level 6",
                          s));
    }
}

void addFramebufferCases(std::vector<Case>& cases) {
  for (FramebufferFormat fb : {FramebufferFormat::RGBA8, FramebufferFormat::RGBA16, FramebufferFormat::RGBA16F}) {
    SparseGridScene s = defaultSparseGridScene();
    s.grid.level = 5;
    s.framebuffer = fb;
    s.flushEachPass = true;
    cases.push_back(
        combinationCase("sparsegrid.framebuffer.flush_each_pass." + str(ref::name(fb)) + ".l5",
                        "glFinish after every pass (" + str(ref::name(fb)) +
                            "): the per-pass quantization of the GL semantics, also on drivers that cache tiles",
                        s));
  }
}

void addDataCases(std::vector<Case>& cases) {
  SparseGridScene s = defaultSparseGridScene();
  s.data.field = "hydrogen_orbital";
  s.grid.level = 7;
  s.framebuffer = FramebufferFormat::RGBA16;
  s.shading.mode = RenderMode::Mip;
  cases.push_back(combinationCase("sparsegrid.data.hydrogen_orbital.l7.mip",
                                  "MIP of an analytic hydrogen 3d orbital (the paper's data set IV is one), level 7",
                                  s));
  s.shading.mode = RenderMode::Iso;
  s.shading.isovalue = 0.3;
  cases.push_back(combinationCase("sparsegrid.data.hydrogen_orbital.l7.iso",
                                  "isosurface 0.3 of the hydrogen 3d orbital, level 7", s));
}

void addHardCases(std::vector<Case>& cases) {
  for (Case& c : figure9Cases()) cases.push_back(std::move(c));
  {  // every sample on a node of the level-4 lattice
    SparseGridScene s = defaultSparseGridScene();
    s.grid.level = 4;
    s.textures.format = TexelFormat::R32F;
    s.framebuffer = FramebufferFormat::RGBA32F;
    latticeCamera(s, glm::dvec3(0.0), 1.0 / 16, 17, 17, 17);
    cases.push_back(
        combinationCase("sparsegrid.hard.nodes.l4", "query points exactly on the nodes of the level-4 full grid", s));
  }
  {  // on the x faces of the finest cells, y and z at cell centres
    SparseGridScene s = defaultSparseGridScene();
    s.grid.level = 4;
    s.textures.format = TexelFormat::R32F;
    s.framebuffer = FramebufferFormat::RGBA32F;
    latticeCamera(s, glm::dvec3(0.0, 1.0 / 32, 1.0 / 32), 1.0 / 16, 17, 16, 16);
    cases.push_back(combinationCase("sparsegrid.hard.cell_faces.l4",
                                    "query points on cell faces (x on nodes, y and z mid-cell)", s));
  }
  // x 2^-24 (one float32 ulp above 0.5) either side of the nodes of the level-4 grid, where LINEAR
  // changes cells, and of the mid-cells, where NEAREST changes texels; y on nodes, z mid-cell.
  for (const bool mid : {false, true})
    for (const ref::Filter filter : {ref::Filter::Linear, ref::Filter::Nearest}) {
      SparseGridScene s = defaultSparseGridScene();
      s.grid.level = 4;
      s.textures.format = TexelFormat::R32F;
      s.framebuffer = FramebufferFormat::RGBA32F;
      s.sampler.filter = filter;
      const ref::PlaneFrame f =
          ref::straddlingFrame(mid ? 1.0 / 32 : 0.0, 1.0 / 16, 16, {0, 1.0 / 16, 0}, 17, {0, 0, 17.0 / 32});
      s.camera.origin = f.origin;
      s.camera.dx = f.dx;
      s.camera.dy = f.dy;
      s.camera.dz = f.dz;
      s.width = f.width;
      s.height = f.height;
      s.planes = f.planes;
      const std::string where = mid ? "mid_cell_ulps" : "node_ulps";
      cases.push_back(combinationCase("sparsegrid.hard." + where + ".l4." + std::string(ref::name(filter)),
                                      std::string("query points one float32 ulp (2^-24) either side of the level-4 ") +
                                          (mid ? "mid-cells" : "nodes") + " in x, " + std::string(ref::name(filter)),
                                      s));
    }
  for (ref::TextureSizing sizing : {ref::TextureSizing::Padded, ref::TextureSizing::Exact}) {
    SparseGridScene s = defaultSparseGridScene();  // samples at 0, 1/8, ..., 1: the last exactly 1.0
    s.grid.level = 5;
    s.textures.sizing = sizing;
    s.framebuffer = FramebufferFormat::RGBA16;
    latticeCamera(s, glm::dvec3(0.0), 1.0 / 8, 9, 9, 9);
    cases.push_back(combinationCase(
        "sparsegrid.hard.coordinate_one." + str(ref::name(sizing)),
        "query points at coordinate 0 and exactly 1.0 on every axis (" + str(ref::name(sizing)) + " textures)", s));
  }
  for (const char* field : {"zero", "constant_one"}) {
    SparseGridScene s = defaultSparseGridScene();
    s.data.field = field;
    s.grid.level = 5;
    s.framebuffer = FramebufferFormat::RGBA8;
    cases.push_back(
        combinationCase(std::string("sparsegrid.hard.data_extremes.") + field,
                        std::string("data at the extreme ") + (field[0] == 'z' ? "0" : "1") + " everywhere, rgba8", s));
  }
  // Extreme floats in float textures; float framebuffer, so nothing clamps or rounds them away.
  // Half floats go in unscaled, so that the texels hold the data itself (the paper's 1/n+ scaling
  // would move them away from the extremes).
  struct Extreme {
    const char* field;
    TexelFormat format;
    ref::ScalingPolicy scaling;
  };
  for (const Extreme& e : {Extreme{"blobs_near_flt_max", TexelFormat::R32F, ref::ScalingPolicy::Scaled},
                           Extreme{"blobs_denormal", TexelFormat::R32F, ref::ScalingPolicy::Scaled},
                           Extreme{"blobs_near_half_max", TexelFormat::R16F, ref::ScalingPolicy::Unscaled},
                           Extreme{"blobs_half_denormal", TexelFormat::R16F, ref::ScalingPolicy::Unscaled}})
    for (ref::Filter filter : {ref::Filter::Linear, ref::Filter::Nearest}) {
      SparseGridScene s = defaultSparseGridScene();
      s.data.field = e.field;
      s.grid.level = 5;
      s.textures.format = e.format;
      s.textures.scaling = e.scaling;
      s.sampler = {filter, ref::Wrap::ClampToEdge, 0.0};
      s.framebuffer = FramebufferFormat::RGBA32F;
      s.shading.mode = RenderMode::Mip;
      const std::string format(ref::name(e.format));
      cases.push_back(combinationCase(
          std::string("sparsegrid.hard.float_extremes.") + e.field + "." + format + "." + str(ref::name(filter)),
          "extreme floats in " + std::string(e.scaling == ref::ScalingPolicy::Unscaled ? "unscaled " : "") + format +
              " textures (" + e.field + "), " + str(ref::name(filter)) + ", rgba32f framebuffer, level 5",
          s));
    }
  for (FramebufferFormat fb : {FramebufferFormat::RGBA8, FramebufferFormat::RGBA32F}) {
    SparseGridScene s = defaultSparseGridScene();
    s.data.field = "ridge";
    s.grid.level = 6;
    s.framebuffer = fb;
    s.shading.mode = RenderMode::Mip;
    cases.push_back(
        combinationCase("sparsegrid.hard.large_negative_surpluses." + str(ref::name(fb)),
                        "a sharp ridge: large negative surpluses, an interpolant below 0 (clamped by fixed point, "
                        "kept by float)",
                        s));
  }
  {
    SparseGridScene s = defaultSparseGridScene();
    s.grid.level = 1;
    cases.push_back(
        combinationCase("sparsegrid.hard.level1", "level 1: one grid (1,1,1), n+ = 1, no negative pass", s));
  }
  for (FramebufferFormat fb : {FramebufferFormat::RGBA8, FramebufferFormat::RGBA32F}) {
    SparseGridScene s = defaultSparseGridScene();
    s.grid.level = 12;
    s.textures.sizing = ref::TextureSizing::Exact;
    s.framebuffer = fb;
    s.width = s.height = 24;
    s.planes = 12;
    cases.push_back(combinationCase("sparsegrid.hard.level12." + str(ref::name(fb)),
                                    "level 12 (199 grids, n+ = 133, 4097-texel textures in 2048-texel bricks), " +
                                        str(ref::name(fb)) + ": built without any full grid",
                                    s));
  }
}

}  // namespace

SparseGridScene defaultSparseGridScene() {
  SparseGridScene s;
  s.data.field = "gaussian_blobs";
  s.grid = {6, true};
  s.textures = {TexelFormat::R16, ref::TextureSizing::Padded, ref::ScalingPolicy::Scaled};  // the paper's choice
  s.sampler = {ref::Filter::Linear, ref::Wrap::ClampToEdge, 0.0};
  s.framebuffer = FramebufferFormat::RGBA8;
  s.shading = {RenderMode::XRay, 0.5, 0.15};
  s.camera = {30.0, 20.0, {}, {}, {}, {}};
  s.width = s.height = 48;
  s.planes = 32;
  return s;
}

std::vector<Case> sparseGridCases() {
  std::vector<Case> cases;
  addMainCases(cases);
  addTextureCases(cases);
  addBrickCases(cases);
  addFramebufferCases(cases);
  addDataCases(cases);
  addHardCases(cases);
  return cases;
}

}  // namespace voxref::conf
