#include "gpu/probe_gl.h"

#include "gpu/gl_error.h"
#include "gpu/gl_objects.h"
#include "gpu/shader_sources.h"

namespace voxref::gpu {
namespace {

ref::ProbeFrame drawSweep(Context& context, const ref::ProbeSweep& sweep) {
  const GlApi& gl = context.gl();
  const ContextInfo& info = context.info();
  ColorTarget target(gl, info.maxRenderbufferSize, ref::FramebufferFormat::RGBA32F, sweep.width, sweep.height);
  std::vector<unsigned char> bytes;  // RGBA8 codes or RGBA32F bits, texel after texel
  for (const auto& texel : sweep.texelCodes)
    for (std::uint32_t c : texel) {
      if (sweep.unorm8) {
        bytes.push_back(static_cast<unsigned char>(c));
        continue;
      }
      for (int b = 0; b < 4; ++b) bytes.push_back(static_cast<unsigned char>(c >> (8 * b)));  // little endian
    }
  const TextureUpload upload =
      sweep.unorm8 ? TextureUpload{GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE} : TextureUpload{GL_RGBA32F, GL_RGBA, GL_FLOAT};
  const Texture3D texture(gl, info.max3DTextureSize, ref::Dims3{sweep.texels, 1, 1}, upload, bytes.data(),
                          ref::SamplerState{ref::Filter::Linear, sweep.wrap, 0.0});
  const Program program(gl, info.glslNumber, shaders::kFullscreenVert, shaders::kProbeSweepFrag, "probe_sweep.frag");
  const VertexArray vao(gl);
  beginFullscreenPass(gl, target, vao, program);
  gl.Disable(GL_BLEND);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_3D, texture.id());
  gl.Uniform1i(program.uniform("tex"), 0);
  gl.Uniform1f(program.uniform("uOrigin"), sweep.uOrigin);
  gl.Uniform1f(program.uniform("uStep"), sweep.uStep);
  gl.Uniform1i(program.uniform("width"), sweep.width);
  gl.DrawArrays(GL_TRIANGLES, 0, 3);
  ref::ProbeFrame frame{sweep.id, ref::FramebufferFormat::RGBA32F, sweep.width, sweep.height, {}};
  target.readRgbaCodes(frame.codes);
  checkGl(gl, std::string("drawing probe ") + std::string(sweep.id));
  return frame;
}

ref::ProbeFrame drawWrite(Context& context, const ref::ProbeWrite& write) {
  const GlApi& gl = context.gl();
  const ContextInfo& info = context.info();
  ColorTarget target(gl, info.maxRenderbufferSize, write.format, write.width, write.height);
  std::vector<float> values;  // layer after layer: the passes
  for (const auto& pass : write.passes)
    for (const auto& px : pass) values.insert(values.end(), px.begin(), px.end());
  const int layers = static_cast<int>(write.passes.size());
  const Texture3D texture(gl, info.max3DTextureSize, ref::Dims3{write.width, write.height, layers},
                          TextureUpload{GL_RGBA32F, GL_RGBA, GL_FLOAT}, values.data(),
                          ref::SamplerState{ref::Filter::Nearest, ref::Wrap::ClampToEdge, 0.0});
  const Program program(gl, info.glslNumber, shaders::kFullscreenVert, shaders::kProbeWriteFrag, "probe_write.frag");
  const VertexArray vao(gl);
  beginFullscreenPass(gl, target, vao, program);
  gl.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  gl.Enable(GL_BLEND);
  gl.BlendEquation(GL_FUNC_ADD);
  if (write.blend == ref::ProbeBlend::OneOne)
    gl.BlendFunc(GL_ONE, GL_ONE);
  else
    gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  gl.ActiveTexture(GL_TEXTURE0);
  gl.BindTexture(GL_TEXTURE_3D, texture.id());
  gl.Uniform1i(program.uniform("values"), 0);
  const GLint layer = program.uniform("layer");
  for (int p = 0; p < layers; ++p) {  // no glFinish between passes: what the driver keeps is the probe
    gl.Uniform1i(layer, p);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
  }
  ref::ProbeFrame frame{write.id, write.format, write.width, write.height, {}};
  target.readRgbaCodes(frame.codes);
  gl.Disable(GL_BLEND);
  checkGl(gl, std::string("drawing probe ") + std::string(write.id));
  return frame;
}

}  // namespace

std::vector<ref::ProbeFrame> renderProbeFramesGl(Context& context, const ref::ProbeDesign& design) {
  std::vector<ref::ProbeFrame> frames;
  for (const ref::ProbeSweep& s : design.sweeps) frames.push_back(drawSweep(context, s));
  for (const ref::ProbeWrite& w : design.writes) frames.push_back(drawWrite(context, w));
  return frames;
}

}  // namespace voxref::gpu
