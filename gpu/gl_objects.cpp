#include "gpu/gl_objects.h"

#include <cstdio>
#include <cstring>

#include "gpu/gl_error.h"
#include "gpu/gl_formats.h"

namespace voxref::gpu {

GlHandle& GlHandle::operator=(GlHandle&& o) noexcept {
  if (this != &o) {
    if (id_ && release_) release_(*gl_, id_);
    gl_ = o.gl_;
    id_ = o.id_;
    release_ = o.release_;
    o.id_ = 0;
  }
  return *this;
}

GlHandle::~GlHandle() {
  if (id_ && release_) release_(*gl_, id_);
}

// --- Texture3D -------------------------------------------------------------------------------

Texture3D::Texture3D(const GlApi& gl, int max3DTextureSize, const ref::Dims3& dims, ref::TexelFormat format,
                     const std::vector<std::uint32_t>& codes, const ref::SamplerState& sampler)
    : Texture3D(
          gl, max3DTextureSize, dims,
          [&] {
            const TexelUpload up = texelUpload(format);
            return TextureUpload{up.internalFormat, up.format, up.type};
          }(),
          packTexels(format, codes).data(), sampler) {}

Texture3D::Texture3D(const GlApi& gl, int max3DTextureSize, const ref::Dims3& dims, const TextureUpload& up,
                     const void* pixels, const ref::SamplerState& sampler) {
  for (int e : dims)
    if (e > max3DTextureSize)
      throw GlUnsupported("a " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
                          std::to_string(dims[2]) + " texture exceeds GL_MAX_3D_TEXTURE_SIZE " +
                          std::to_string(max3DTextureSize));
  GLuint id = 0;
  gl.GenTextures(1, &id);
  handle_ = GlHandle(&gl, id, [](const GlApi& g, GLuint i) { g.DeleteTextures(1, &i); });
  gl.BindTexture(GL_TEXTURE_3D, id);
  gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  gl.TexImage3D(GL_TEXTURE_3D, 0, up.internalFormat, dims[0], dims[1], dims[2], 0, up.format, up.type, pixels);
  const GLint filter = sampler.filter == ref::Filter::Linear ? GL_LINEAR : GL_NEAREST;
  const GLint wrap = glWrap(sampler.wrap);
  gl.TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, filter);
  gl.TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, filter);
  gl.TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, wrap);
  gl.TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, wrap);
  gl.TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, wrap);
  gl.TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_BASE_LEVEL, 0);
  gl.TexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, 0);
  const GLfloat border[4] = {static_cast<GLfloat>(sampler.borderRed), 0.0f, 0.0f, 0.0f};
  gl.TexParameterfv(GL_TEXTURE_3D, GL_TEXTURE_BORDER_COLOR, border);
  checkGl(
      gl, "creating a 3D texture (internal format 0x" + [&] {
        char b[16];
        std::snprintf(b, sizeof b, "%x", up.internalFormat);
        return std::string(b);
      }() + ")");
}

// --- ColorTarget -----------------------------------------------------------------------------

ColorTarget::ColorTarget(const GlApi& gl, int maxRenderbufferSize, ref::FramebufferFormat format, int width, int height)
    : gl_(&gl), format_(format), width_(width), height_(height) {
  if (!ref::existsInGl(format))
    throw GlUnsupported("GL has no " + std::string(ref::name(format)) + " colour format (emulated only)");
  if (width > maxRenderbufferSize || height > maxRenderbufferSize)
    throw GlUnsupported("a " + std::to_string(width) + "x" + std::to_string(height) +
                        " target exceeds GL_MAX_RENDERBUFFER_SIZE " + std::to_string(maxRenderbufferSize));
  GLuint rb = 0, fb = 0;
  gl.GenRenderbuffers(1, &rb);
  renderbuffer_ = GlHandle(&gl, rb, [](const GlApi& g, GLuint i) { g.DeleteRenderbuffers(1, &i); });
  gl.BindRenderbuffer(GL_RENDERBUFFER, rb);
  gl.RenderbufferStorage(GL_RENDERBUFFER, colorInternalFormat(format), width, height);
  gl.GenFramebuffers(1, &fb);
  framebuffer_ = GlHandle(&gl, fb, [](const GlApi& g, GLuint i) { g.DeleteFramebuffers(1, &i); });
  gl.BindFramebuffer(GL_FRAMEBUFFER, fb);
  gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
  const GLenum status = gl.CheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw GlError("framebuffer with a " + std::string(ref::name(format)) + " colour buffer is incomplete (status 0x" +
                  std::to_string(status) + ")");
  const GLenum drawBuffer = GL_COLOR_ATTACHMENT0;
  gl.DrawBuffers(1, &drawBuffer);
  gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
  checkGl(gl, "creating a " + std::string(ref::name(format)) + " colour target");
}

void ColorTarget::bind() const { gl_->BindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id()); }

void ColorTarget::readRedCodes(std::vector<std::uint32_t>& out) const {
  const ReadbackType rt = readbackType(format_);
  const std::size_t n = static_cast<std::size_t>(width_) * height_;
  std::vector<unsigned char> bytes(n * rt.bytes);
  gl_->PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_->ReadPixels(0, 0, width_, height_, GL_RED, rt.type, bytes.data());
  checkGl(*gl_, "reading back the " + std::string(ref::name(format_)) + " target");
  out.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + i * rt.bytes, rt.bytes);  // little endian, as GL hands it over
    out[i] = v;
  }
}

void ColorTarget::readRgbaCodes(std::vector<std::array<std::uint32_t, 4>>& out) const {
  const ReadbackType rt = readbackType(format_);
  const std::size_t n = static_cast<std::size_t>(width_) * height_;
  std::vector<unsigned char> bytes(n * 4 * rt.bytes);
  gl_->PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_->ReadPixels(0, 0, width_, height_, GL_RGBA, rt.type, bytes.data());
  checkGl(*gl_, "reading back the " + std::string(ref::name(format_)) + " target (RGBA)");
  out.assign(n, {0, 0, 0, 0});
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < 4; ++c)
      std::memcpy(&out[i][c], bytes.data() + (i * 4 + c) * rt.bytes, rt.bytes);  // little endian
}

void ColorTarget::readRgba8(std::vector<std::array<std::uint8_t, 4>>& out) const {
  if (format_ != ref::FramebufferFormat::RGBA8) throw GlError("readRgba8 reads RGBA8 targets only");
  out.resize(static_cast<std::size_t>(width_) * height_);
  gl_->PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl_->ReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  checkGl(*gl_, "reading back the rgba8 target");
}

// --- Program ---------------------------------------------------------------------------------

namespace {

// The info log of a shader or program (glGetShaderiv/InfoLog or glGetProgramiv/InfoLog).
template <class GetIv, class GetLog>
std::string infoLog(GLuint object, GetIv getIv, GetLog getLog) {
  GLint len = 0;
  getIv(object, GL_INFO_LOG_LENGTH, &len);
  std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
  getLog(object, len, nullptr, log.data());
  return log.c_str();
}

GLuint compile(const GlApi& gl, GLenum stage, int glslNumber, std::string_view source, std::string_view sourceName,
               std::string_view library = {}) {
  const std::string version = glslNumber >= 450   ? "450 core"
                              : glslNumber >= 430 ? "430 core"
                              : glslNumber >= 400 ? "400 core"
                                                  : "330 core";
  const std::string prelude = "#version " + version + "\n#define PRECISE " + (glslNumber >= 400 ? "precise" : "") +
                              "\n" + std::string(library) + "\n#line 1\n";
  const std::string full = prelude + std::string(source);
  const GLuint shader = gl.CreateShader(stage);
  const char* text = full.c_str();
  gl.ShaderSource(shader, 1, &text, nullptr);
  gl.CompileShader(shader);
  GLint ok = 0;
  gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    const std::string log = infoLog(shader, gl.GetShaderiv, gl.GetShaderInfoLog);
    gl.DeleteShader(shader);
    throw ShaderError(
        std::string(sourceName) + (stage == GL_VERTEX_SHADER ? " (vertex)" : " (fragment)") + " failed to compile",
        log);
  }
  return shader;
}

}  // namespace

Program::Program(const GlApi& gl, int glslNumber, std::string_view vertexSource, std::string_view fragmentSource,
                 std::string_view sourceName, std::string_view fragmentLibrary, Uniforms uniforms)
    : gl_(&gl), name_(sourceName), uniforms_(uniforms) {
  const GLuint vs = compile(gl, GL_VERTEX_SHADER, glslNumber, vertexSource, sourceName);
  GLuint fs = 0;
  try {
    fs = compile(gl, GL_FRAGMENT_SHADER, glslNumber, fragmentSource, sourceName, fragmentLibrary);
  } catch (...) {
    gl.DeleteShader(vs);
    throw;
  }
  const GLuint program = gl.CreateProgram();
  handle_ = GlHandle(&gl, program, [](const GlApi& g, GLuint i) { g.DeleteProgram(i); });
  gl.AttachShader(program, vs);
  gl.AttachShader(program, fs);
  gl.LinkProgram(program);
  gl.DeleteShader(vs);
  gl.DeleteShader(fs);
  GLint ok = 0;
  gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok)
    throw ShaderError(std::string(sourceName) + " failed to link",
                      infoLog(program, gl.GetProgramiv, gl.GetProgramInfoLog));
  checkGl(gl, "building program " + name_);
}

void Program::use() const { gl_->UseProgram(handle_.id()); }

GLint Program::uniform(const char* uniformName) const {
  const GLint loc = gl_->GetUniformLocation(handle_.id(), uniformName);
  if (loc < 0 && uniforms_ == Uniforms::Required)
    throw GlError("program " + name_ + " has no active uniform '" + uniformName + "'");
  return loc;
}

// --- VertexArray -----------------------------------------------------------------------------

VertexArray::VertexArray(const GlApi& gl) : gl_(&gl) {
  GLuint id = 0;
  gl.GenVertexArrays(1, &id);
  handle_ = GlHandle(&gl, id, [](const GlApi& g, GLuint i) { g.DeleteVertexArrays(1, &i); });
}

void VertexArray::bind() const { gl_->BindVertexArray(handle_.id()); }

void beginFullscreenPass(const GlApi& gl, const ColorTarget& target, const VertexArray& vao, const Program& program) {
  target.bind();
  vao.bind();
  program.use();
  gl.Viewport(0, 0, target.width(), target.height());
}

}  // namespace voxref::gpu
