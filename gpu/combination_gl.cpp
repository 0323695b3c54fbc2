#include "gpu/combination_gl.h"

#include <cmath>

#include "gpu/gl_error.h"
#include "gpu/gl_formats.h"
#include "gpu/gl_objects.h"

namespace voxref::gpu {

ref::CodePlanes renderCombinationGl(Context& context, const ref::CombinationTextures& textures,
                                    const ref::PlaneFrame& frame, const ref::SamplerState& sampler,
                                    ref::FramebufferFormat format, const CombinationGlOptions& options,
                                    const std::function<void(int)>& progress) {
  const GlApi& gl = context.gl();
  const ContextInfo& info = context.info();
  ColorTarget target(gl, info.maxRenderbufferSize, format, frame.width, frame.height);
  std::vector<Texture3D> gridTextures;
  gridTextures.reserve(textures.textures.size());
  for (const ref::GridTexture& t : textures.textures)
    gridTextures.emplace_back(gl, info.max3DTextureSize, t.dims, textures.format, t.codes, sampler);
  const Program program = buildStageProgram(context, combinationStage(), options.shader);
  VertexArray vao(gl);

  beginFullscreenPass(gl, target, vao, program);
  gl.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  gl.Enable(GL_BLEND);
  gl.BlendFunc(GL_ONE, GL_ONE);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.Uniform1i(program.uniform("grid"), 0);
  // Every value below is exactly representable in float32 (plane_frame.h), so the casts are exact.
  gl.Uniform3f(program.uniform("pixelDx"), float(frame.dx.x), float(frame.dx.y), float(frame.dx.z));
  gl.Uniform3f(program.uniform("pixelDy"), float(frame.dy.x), float(frame.dy.y), float(frame.dy.z));
  const GLint planeOrigin = program.uniform("planeOrigin");
  const GLint nodeScale = program.uniform("nodeScale");
  const GLint extent = program.uniform("extent");
  const GLint brickOrigin = program.uniform("brickOrigin");
  const GLint cellLo = program.uniform("cellLo");
  const GLint cellHi = program.uniform("cellHi");
  checkGl(gl, "setting up the combination passes");

  ref::CodePlanes out{format, frame.width, frame.height, frame.planes, {}};
  out.codes.reserve(static_cast<std::size_t>(frame.width) * frame.height * frame.planes);
  std::vector<std::uint32_t> plane;
  for (int k = 0; k < frame.planes; ++k) {
    const glm::dvec3 o = frame.planeOrigin(k);
    gl.Uniform3f(planeOrigin, float(o.x), float(o.y), float(o.z));
    gl.Clear(GL_COLOR_BUFFER_BIT);
    for (const ref::CombinationPass& pass : textures.passes) {
      const ref::GridTexture& t = textures.textures[pass.texture];
      gl.BindTexture(GL_TEXTURE_3D, gridTextures[pass.texture].id());
      gl.Uniform3f(nodeScale, std::ldexp(1.0f, t.levels[0]), std::ldexp(1.0f, t.levels[1]),
                   std::ldexp(1.0f, t.levels[2]));
      gl.Uniform3f(extent, float(t.dims[0]), float(t.dims[1]), float(t.dims[2]));
      gl.Uniform3f(brickOrigin, float(t.origin[0]), float(t.origin[1]), float(t.origin[2]));
      gl.Uniform3f(cellLo, float(t.cellLo[0]), float(t.cellLo[1]), float(t.cellLo[2]));
      gl.Uniform3f(cellHi, float(t.cellHi[0]), float(t.cellHi[1]), float(t.cellHi[2]));
      gl.BlendEquation(glBlendEquationOf(pass.equation));
      gl.DrawArrays(GL_TRIANGLES, 0, 3);
      if (options.flushEachPass) gl.Finish();
    }
    target.readRedCodes(plane);
    out.codes.insert(out.codes.end(), plane.begin(), plane.end());
    checkGl(gl, "drawing plane " + std::to_string(k));
    if (progress) progress(k + 1);
  }
  gl.Disable(GL_BLEND);
  return out;
}

}  // namespace voxref::gpu
