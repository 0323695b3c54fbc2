#include "gpu/timevarying_gl.h"

#include <stdexcept>
#include <vector>

#include "gpu/gl_error.h"
#include "gpu/gl_objects.h"

namespace voxref::gpu {
namespace {

TextureUpload indexUpload(ref::IndexEncoding e) {
  switch (e) {
    case ref::IndexEncoding::NormalizedRgba16:
      return {GL_RGBA16, GL_RGBA, GL_UNSIGNED_SHORT};
    case ref::IndexEncoding::NormalizedFloat:
      return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
    default:
      return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
  }
}

// Index texels in the upload's type: bytes, shorts, or the float bits as they are.
std::vector<unsigned char> indexBytes(const ref::IndexTexture& index) {
  const std::size_t cb = index.encoding == ref::IndexEncoding::NormalizedRgba16  ? 2
                         : index.encoding == ref::IndexEncoding::NormalizedFloat ? 4
                                                                                 : 1;
  std::vector<unsigned char> out(index.texels.size() * cb);
  for (std::size_t i = 0; i < index.texels.size(); ++i)
    for (std::size_t k = 0; k < cb; ++k) out[i * cb + k] = static_cast<unsigned char>(index.texels[i] >> (8 * k));
  return out;
}

// Sets the decoder's uniforms for time step `step` (a user's shader may leave some out: its
// Program tolerates them, shader_override.h).
void setDecoderUniforms(const GlApi& gl, const Program& program, ref::DecoderVariant v, const ref::TimeVaryingLayout& L,
                        int step) {
  const auto slot = ref::indexSlot(L, step);
  const float S = static_cast<float>(L.indexSlots), n = static_cast<float>(L.cells);
  switch (v) {
    case ref::DecoderVariant::Literal:
      gl.Uniform3f(program.uniform("origin"), float(slot[0]) / S, float(slot[1]) / S, float(slot[2]) / S);
      break;
    case ref::DecoderVariant::Paper:
      gl.Uniform3f(program.uniform("slotOrigin"), float(slot[0]) / S, float(slot[1]) / S, float(slot[2]) / S);
      gl.Uniform1f(program.uniform("slotScale"), 1.0f / S);
      gl.Uniform1f(program.uniform("cellSize"), 1.0f / n);
      gl.Uniform1f(program.uniform("blockScale"), n / static_cast<float>(L.blockSlots));
      break;
    case ref::DecoderVariant::TexelCentre:
      gl.Uniform3f(program.uniform("slotTexel"), float(slot[0] * L.cells), float(slot[1] * L.cells),
                   float(slot[2] * L.cells));
      gl.Uniform1f(program.uniform("indexSize"), float(L.indexSlots * L.cells));
      gl.Uniform1f(program.uniform("cells"), n);
      gl.Uniform1f(program.uniform("side"), float(L.side));
      gl.Uniform1f(program.uniform("blockSide"), float(L.blockSide));
      gl.Uniform1f(program.uniform("refinementSize"), float(L.blockSlots * L.blockSide));
      break;
    case ref::DecoderVariant::TexelFetch:
      gl.Uniform3i(program.uniform("slotTexelI"), slot[0] * L.cells, slot[1] * L.cells, slot[2] * L.cells);
      gl.Uniform1i(program.uniform("cellsI"), L.cells);
      gl.Uniform1i(program.uniform("sideI"), L.side);
      gl.Uniform1i(program.uniform("blockSideI"), L.blockSide);
      gl.Uniform1f(program.uniform("cells"), n);
      gl.Uniform1f(program.uniform("side"), float(L.side));
      break;
  }
}

enum class Mode { DecodePlanes, Composite };

// `index` and `refinement` in place of the textures' own (the address textures of measureFetchesGl).
ref::RgbaStack run(Context& context, const ref::TimeVaryingTextures& tex, const ref::IndexTexture& indexTexture,
                   const ref::RefinementTexture& refinementTexture, ref::DecoderVariant variant, int step,
                   const ref::PlaneFrame& frame, Mode mode, const std::function<void(int)>& progress,
                   const ShaderOverride* shader) {
  if (const std::string why = ref::decoderIncompatibility(variant, tex.layout, tex.index.encoding); !why.empty())
    throw std::invalid_argument(why);
  if (step < 0 || step >= tex.layout.timeSteps)
    throw std::invalid_argument("time step " + std::to_string(step) + " is outside the series");
  const GlApi& gl = context.gl();
  const ContextInfo& info = context.info();
  const ref::SamplerState nearest{ref::Filter::Nearest, ref::Wrap::ClampToEdge, 0.0};
  const std::vector<unsigned char> ib = indexBytes(indexTexture);
  Texture3D index(gl, info.max3DTextureSize, indexTexture.dims, indexUpload(indexTexture.encoding), ib.data(), nearest);
  Texture3D refinement(gl, info.max3DTextureSize, refinementTexture.dims, {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE},
                       refinementTexture.texels.data(), nearest);
  ColorTarget target(gl, info.maxRenderbufferSize, ref::FramebufferFormat::RGBA8, frame.width, frame.height);
  const Program program = buildStageProgram(context, decoderStage(variant), shader);
  VertexArray vao(gl);
  beginFullscreenPass(gl, target, vao, program);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_3D, index.id());
  gl.ActiveTexture(GL_TEXTURE1);
  gl.BindTexture(GL_TEXTURE_3D, refinement.id());
  gl.Uniform1i(program.uniform("texIndex"), 0);
  gl.Uniform1i(program.uniform("texRefinement"), 1);
  gl.Uniform3f(program.uniform("pixelDx"), float(frame.dx.x), float(frame.dx.y), float(frame.dx.z));
  gl.Uniform3f(program.uniform("pixelDy"), float(frame.dy.x), float(frame.dy.y), float(frame.dy.z));
  setDecoderUniforms(gl, program, variant, tex.layout, step);
  const GLint planeOrigin = program.uniform("planeOrigin");
  gl.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  if (mode == Mode::Composite) {
    gl.Enable(GL_BLEND);
    gl.BlendEquation(GL_FUNC_ADD);
    gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.Clear(GL_COLOR_BUFFER_BIT);
  } else {
    gl.Disable(GL_BLEND);
  }
  checkGl(gl, "setting up the time-varying decoder");
  ref::RgbaStack out{frame.width, frame.height, mode == Mode::Composite ? 1 : frame.planes, {}};
  std::vector<ref::Rgba8> plane;
  for (int n = 0; n < frame.planes; ++n) {
    const int k = mode == Mode::Composite ? frame.planes - 1 - n : n;  // back to front when compositing
    const glm::dvec3 o = frame.planeOrigin(k);
    gl.Uniform3f(planeOrigin, float(o.x), float(o.y), float(o.z));
    if (mode == Mode::DecodePlanes) gl.Clear(GL_COLOR_BUFFER_BIT);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    if (mode == Mode::DecodePlanes) {
      target.readRgba8(plane);
      out.colours.insert(out.colours.end(), plane.begin(), plane.end());
    }
    checkGl(gl, "decoding plane " + std::to_string(k));
    if (progress) progress(n + 1);
  }
  if (mode == Mode::Composite) {
    target.readRgba8(plane);
    out.colours = plane;
  }
  gl.Disable(GL_BLEND);
  return out;
}

}  // namespace

ref::RgbaStack decodePlanesGl(Context& context, const ref::TimeVaryingTextures& textures, ref::DecoderVariant variant,
                              int step, const ref::PlaneFrame& frame, const std::function<void(int)>& progress,
                              const ShaderOverride* shader) {
  return run(context, textures, textures.index, textures.refinement, variant, step, frame, Mode::DecodePlanes, progress,
             shader);
}

ref::RgbaStack compositeGl(Context& context, const ref::TimeVaryingTextures& textures, ref::DecoderVariant variant,
                           int step, const ref::PlaneFrame& frame, const std::function<void(int)>& progress,
                           const ShaderOverride* shader) {
  return run(context, textures, textures.index, textures.refinement, variant, step, frame, Mode::Composite, progress,
             shader);
}

ref::MeasuredFetches measureFetchesGl(Context& context, const ref::TimeVaryingTextures& textures,
                                      ref::DecoderVariant variant, int step, const ref::PlaneFrame& frame,
                                      const ShaderOverride* shader) {
  const ref::IndexTexture indexAddresses = ref::addressIndexTexture(textures.index);
  const ref::RefinementTexture refinementAddresses = ref::addressRefinementTexture(textures.refinement);
  const ref::RgbaStack indexPass =
      run(context, textures, indexAddresses, textures.refinement, variant, step, frame, Mode::DecodePlanes, {}, shader);
  const ref::RgbaStack refinementPass =
      run(context, textures, textures.index, refinementAddresses, variant, step, frame, Mode::DecodePlanes, {}, shader);
  return ref::fetchesFromAddressPasses(textures, frame, indexPass, refinementPass);
}

}  // namespace voxref::gpu
