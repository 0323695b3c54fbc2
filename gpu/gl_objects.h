// RAII owners of GL objects. Each is move-only, deletes its object in the destructor, and
// checks GL errors after creation (GlError, GlUnsupported, ShaderError from gl_error.h).
// The context must outlive the objects and be current.
#pragma once

#include <GL/glcorearb.h>

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/gl_api.h"
#include "reference/common/gl_state.h"
#include "reference/common/volume.h"

namespace voxref::gpu {

class GlHandle {
 public:
  GlHandle() = default;
  GlHandle(const GlApi* gl, GLuint id, void (*release)(const GlApi&, GLuint)) : gl_(gl), id_(id), release_(release) {}
  GlHandle(GlHandle&& o) noexcept : gl_(o.gl_), id_(o.id_), release_(o.release_) { o.id_ = 0; }
  GlHandle& operator=(GlHandle&& o) noexcept;
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;
  ~GlHandle();
  GLuint id() const { return id_; }

 private:
  const GlApi* gl_ = nullptr;
  GLuint id_ = 0;
  void (*release_)(const GlApi&, GLuint) = nullptr;
};

// A 3D texture holding stored red-channel codes (texel_format.h) uploaded without conversion:
// unsigned bytes / shorts for unorm formats, GL_HALF_FLOAT bits, GL_FLOAT bits. One level, no
// mipmaps. Throws GlUnsupported when an extent exceeds GL_MAX_3D_TEXTURE_SIZE.
struct TextureUpload {
  GLint internalFormat;
  GLenum format;
  GLenum type;
};

class Texture3D {
 public:
  Texture3D(const GlApi& gl, int max3DTextureSize, const ref::Dims3& dims, ref::TexelFormat format,
            const std::vector<std::uint32_t>& codes, const ref::SamplerState& sampler);
  // Any format: `pixels` in the layout of `upload` (glTexImage3D's format and type).
  Texture3D(const GlApi& gl, int max3DTextureSize, const ref::Dims3& dims, const TextureUpload& upload,
            const void* pixels, const ref::SamplerState& sampler);
  GLuint id() const { return handle_.id(); }

 private:
  GlHandle handle_;
};

// A framebuffer object with one colour renderbuffer. Throws GlUnsupported for RGBA12 (no such
// GL format) and for sizes over GL_MAX_RENDERBUFFER_SIZE, GlError when incomplete.
class ColorTarget {
 public:
  ColorTarget(const GlApi& gl, int maxRenderbufferSize, ref::FramebufferFormat format, int width, int height);
  void bind() const;
  // The red channel's stored codes (unorm codes, half bits or float bits) of the whole target,
  // read with the format's native type, row 0 at the bottom.
  void readRedCodes(std::vector<std::uint32_t>& out) const;
  // All four channels of an RGBA8 target as bytes, row 0 at the bottom (GlError for other formats).
  void readRgba8(std::vector<std::array<std::uint8_t, 4>>& out) const;
  // All four channels' stored codes (unorm codes, half bits or float bits) in the format's native
  // type, row 0 at the bottom.
  void readRgbaCodes(std::vector<std::array<std::uint32_t, 4>>& out) const;
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  const GlApi* gl_;
  ref::FramebufferFormat format_;
  int width_, height_;
  GlHandle renderbuffer_;
  GlHandle framebuffer_;
};

// A linked program. The sources get a prelude: `#version <glsl>`, `#define PRECISE precise`
// (empty before GLSL 4.00, which has no `precise`), the fragment library (shared functions such as
// sample_point.glsl), then `#line 1`, so info-log line numbers are the source's own. Throws
// ShaderError with the log and the source name.
class Program {
 public:
  // Required: uniform() throws for a name the program does not use (a built-in shader that lost a
  // uniform is a bug). Optional: uniform() returns -1 for it, which glUniform* ignores (a user's
  // shader, shader_override.h, may leave out what it does not read).
  enum class Uniforms { Required, Optional };
  Program(const GlApi& gl, int glslNumber, std::string_view vertexSource, std::string_view fragmentSource,
          std::string_view sourceName, std::string_view fragmentLibrary = {}, Uniforms uniforms = Uniforms::Required);
  void use() const;
  // Location of a uniform; for Uniforms::Required throws GlError if the program has no active
  // uniform of that name.
  GLint uniform(const char* name) const;

 private:
  const GlApi* gl_;
  GlHandle handle_;
  std::string name_;
  Uniforms uniforms_;
};

// An empty vertex array object, for attribute-less full-screen triangles (core profile needs one).
class VertexArray {
 public:
  explicit VertexArray(const GlApi& gl);
  void bind() const;

 private:
  const GlApi* gl_;
  GlHandle handle_;
};

// The start of every full-screen pass: the target, the (attribute-less) vertex array and the
// program bound, the viewport over the whole target.
void beginFullscreenPass(const GlApi& gl, const ColorTarget& target, const VertexArray& vao, const Program& program);

}  // namespace voxref::gpu
