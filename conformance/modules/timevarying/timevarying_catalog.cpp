#include "conformance/modules/timevarying/timevarying_catalog.h"

#include "conformance/modules/timevarying/timevarying_conf.h"
#include "gpu/gl_error.h"
#include "gpu/timevarying_gl.h"

namespace voxref::conf {
namespace {

struct Config {
  const char* name;
  ref::DecoderVariant decoder;
  ref::IndexEncoding encoding;
  bool corrected;  // must fetch every voxel right
};

const Config kConfigs[] = {
    {"paper_rgba8", ref::DecoderVariant::Paper, ref::IndexEncoding::NormalizedRgba8, false},
    {"paper_rgba16", ref::DecoderVariant::Paper, ref::IndexEncoding::NormalizedRgba16, false},
    {"paper_float", ref::DecoderVariant::Paper, ref::IndexEncoding::NormalizedFloat, false},
    {"texel_centre", ref::DecoderVariant::TexelCentre, ref::IndexEncoding::BlockRgba8, true},
    {"texel_fetch", ref::DecoderVariant::TexelFetch, ref::IndexEncoding::BlockRgba8, true},
};

TimeVaryingScene blobs(const Config& c) {
  TimeVaryingScene s;
  s.data = "blobs";
  s.side = 32;
  s.steps = 6;
  s.encoding.level = 2;  // 4^3 cells of 8^3 voxels
  s.encoding.encoding = c.encoding;
  s.decoder = c.decoder;
  return s;
}

// The texture capacity exceeded: a clear error at encoding time, and a GL texture over the
// context's limit refused as unsupported, never a corrupt texture.
CaseResult capacityExceeded(CaseContext& ctx) {
  CaseResult r;
  r.system = "timevarying";
  TimeVaryingScene s = blobs(kConfigs[4]);
  s.encoding.maxTextureExtent = 16;
  const ref::TimeSeries series = makeSeries(s);
  std::string encodeError;
  try {
    ref::encodeTimeVarying(series, ref::transferFunction("gray"), s.encoding);
  } catch (const ref::CapacityError& e) {
    encodeError = e.what();
  }
  const bool encodeOk = encodeError.find("texels per axis") != std::string::npos &&
                        encodeError.find("the limit is 16") != std::string::npos;
  r.oracles.push_back(
      {"encode",
       encodeOk ? Verdict::Pass : Verdict::Fail,
       encodeOk ? "CapacityError: " + encodeError : "no clear capacity error (got '" + encodeError + "')",
       {}});
  if (ctx.gl()) {
    // A refinement texture beyond GL_MAX_3D_TEXTURE_SIZE: the GL path must refuse it.
    ref::TimeVaryingTextures tex =
        ref::encodeTimeVarying(series, ref::transferFunction("gray"), blobs(kConfigs[4]).encoding);
    const int big = ctx.gl()->info().max3DTextureSize + 1;
    tex.refinement.dims = {big, 1, 1};
    tex.refinement.texels.assign(static_cast<std::size_t>(big) * 4, 0);
    std::string glError;
    try {
      gpu::decodePlanesGl(*ctx.gl(), tex, ref::DecoderVariant::TexelFetch, 0,
                          ref::explicitFrame({0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 0.5}, 2, 2, 2));
    } catch (const gpu::GlUnsupported& e) {
      glError = e.what();
    }
    const bool glOk = glError.find("exceeds GL_MAX_3D_TEXTURE_SIZE") != std::string::npos;
    r.oracles.push_back({"gl",
                         glOk ? Verdict::Pass : Verdict::Fail,
                         glOk ? "GlUnsupported: " + glError : "the GL path did not refuse the texture",
                         {},
                         Judge::GlBehaviour});
  }
  concludeFromOracles(r);
  return r;
}

}  // namespace

std::vector<Case> timeVaryingCases() {
  std::vector<Case> cases;
  const char* frames[] = {"voxel_centres", "voxel_faces", "face_ulps", "block_faces", "coordinate_one", "orbit"};
  for (const Config& c : kConfigs)
    for (const char* frame : frames) {
      TimeVaryingScene s = blobs(c);
      s.frame = frame;
      cases.push_back(timeVaryingCase(std::string("timevarying.decode.") + c.name + "." + frame,
                                      std::string("decode every plane of 6 steps of 32^3 blobs with the ") + c.name +
                                          " decoder at " + frame +
                                          (c.corrected ? " (corrected: every fetch right)" : ""),
                                      s, {c.corrected, false}));
    }
  for (const char* frame : {"voxel_centres", "orbit"}) {
    TimeVaryingScene s;  // the paper's configuration: 128^3, level 4, both textures 128^3
    s.data = "blobs";
    s.side = 128;
    s.steps = 2;
    s.encoding.level = 4;
    s.encoding.paperLayout = true;
    s.encoding.encoding = ref::IndexEncoding::NormalizedRgba8;
    s.frame = frame;
    for (ref::DecoderVariant v : {ref::DecoderVariant::Literal, ref::DecoderVariant::Paper}) {
      s.decoder = v;
      const bool literal = v == ref::DecoderVariant::Literal;
      cases.push_back(timeVaryingCase(
          std::string("timevarying.decode.") + (literal ? "literal" : "paper_layout") + "." + frame,
          literal ? std::string("the appendix shader word for word (DR / TEX_DIM = 0) on the paper's layout, ") + frame
                  : std::string("the appendix shader with a float division on the paper's layout, ") + frame,
          s, {false, literal}));
    }
  }
  for (const char* data : {"blobs", "plume"}) {
    for (const Config& c : {kConfigs[0], kConfigs[4]}) {
      TimeVaryingScene s = blobs(c);
      if (std::string(data) == "plume") {
        s.data = "plume_sparseness";  // the paper's data set 3 at level 4, as its Table 3
        s.side = 128;
        s.steps = 36;
        s.sparseness = 0.9951;
        s.encoding.level = 4;
        s.onlySteps = {12, 35};
        s.transfer = "plume";
      } else {
        s.onlySteps = {0, 5};
      }
      s.composite = true;
      s.frame = "orbit";
      s.width = s.height = 96;
      s.planes = 64;
      cases.push_back(timeVaryingCase(
          std::string("timevarying.composite.") + c.name + "." + data,
          std::string("view-aligned slices composited back to front (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) into rgba8: ") +
              data + ", " + c.name,
          s, {c.corrected, false}));
    }
  }
  {
    TimeVaryingScene s = blobs(kConfigs[4]);
    s.data = "empty_noise_full";
    s.steps = 3;
    s.transfer = "opaque";  // values >= 200 are opaque: the full step's cells (255) carry alpha 255
    s.encoding.alphaOne = ref::AlphaOnePolicy::Paper;
    cases.push_back(timeVaryingCase(
        "timevarying.hard.flag_collision.paper",
        "a homogeneous colour with alpha 1 stored as the paper does: it reads as a refinement flag", s, {false, true}));
    s.encoding.alphaOne = ref::AlphaOnePolicy::Refine;
    cases.push_back(timeVaryingCase(
        "timevarying.hard.flag_collision.refine",
        "the same colours with the corrected encoder (such cells refined): every fetch right", s, {true, false}));
  }
  {
    TimeVaryingScene s = blobs(kConfigs[4]);
    s.encoding.hashBits = 3;  // eight hash values: distinct blocks collide, the full comparison keeps them apart
    cases.push_back(timeVaryingCase("timevarying.hard.hash_collisions",
                                    "block hashes of 3 bits: collisions caught by the full comparison", s,
                                    {true, false}));
  }
  for (const Config& c : kConfigs) {  // every decoder: the constant extremes go through each one's addressing
    TimeVaryingScene s = blobs(c);
    s.data = "empty_noise_full";
    s.steps = 3;
    cases.push_back(
        timeVaryingCase(std::string("timevarying.hard.empty_noise_full.") + c.name,
                        "a time step entirely empty, one of noise, one entirely full (" + std::string(c.name) + ")", s,
                        {c.corrected, false}));
  }
  Case capacity;
  capacity.id = "timevarying.hard.capacity_exceeded";
  capacity.system = "timevarying";
  capacity.description =
      "textures over the capacity: a clear error when encoding, an unsupported texture on GL, never a corrupt one";
  capacity.run = capacityExceeded;
  cases.push_back(capacity);
  return cases;
}

}  // namespace voxref::conf
