#include "gpu/gl_formats.h"

#include <cstring>

#include "gpu/gl_error.h"
#include "reference/common/texel_format.h"

namespace voxref::gpu {

TexelUpload texelUpload(ref::TexelFormat format) {
  switch (format) {
    case ref::TexelFormat::R8:
      return {GL_R8, GL_RED, GL_UNSIGNED_BYTE};
    case ref::TexelFormat::RGBA8:
      return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
    case ref::TexelFormat::R16:
      return {GL_R16, GL_RED, GL_UNSIGNED_SHORT};
    case ref::TexelFormat::R16F:
      return {GL_R16F, GL_RED, GL_HALF_FLOAT};
    case ref::TexelFormat::R32F:
      return {GL_R32F, GL_RED, GL_FLOAT};
  }
  throw GlUnsupported("unknown texel format");
}

std::vector<unsigned char> packTexels(ref::TexelFormat format, const std::vector<std::uint32_t>& codes) {
  const std::size_t texelBytes = static_cast<std::size_t>(ref::bytesPerTexel(format));
  const std::size_t channelBytes = format == ref::TexelFormat::RGBA8 ? 1 : texelBytes;
  std::vector<unsigned char> bytes(codes.size() * texelBytes, 0);
  for (std::size_t i = 0; i < codes.size(); ++i) std::memcpy(bytes.data() + i * texelBytes, &codes[i], channelBytes);
  return bytes;
}

GLint glWrap(ref::Wrap wrap) {
  switch (wrap) {
    case ref::Wrap::ClampToEdge:
      return GL_CLAMP_TO_EDGE;
    case ref::Wrap::Repeat:
      return GL_REPEAT;
    case ref::Wrap::ClampToBorder:
      return GL_CLAMP_TO_BORDER;
  }
  return GL_CLAMP_TO_EDGE;
}

GLenum glBlendEquationOf(ref::BlendEquation e) {
  return e == ref::BlendEquation::FuncAdd ? GL_FUNC_ADD : GL_FUNC_REVERSE_SUBTRACT;
}

GLenum colorInternalFormat(ref::FramebufferFormat format) {
  switch (format) {
    case ref::FramebufferFormat::RGBA8:
      return GL_RGBA8;
    case ref::FramebufferFormat::RGBA16:
      return GL_RGBA16;
    case ref::FramebufferFormat::RGBA16F:
      return GL_RGBA16F;
    case ref::FramebufferFormat::RGBA32F:
      return GL_RGBA32F;
    case ref::FramebufferFormat::RGBA12:
      break;
  }
  throw GlUnsupported("GL has no " + std::string(ref::name(format)) + " colour format");
}

ReadbackType readbackType(ref::FramebufferFormat format) {
  switch (format) {
    case ref::FramebufferFormat::RGBA8:
      return {GL_UNSIGNED_BYTE, 1};
    case ref::FramebufferFormat::RGBA16:
      return {GL_UNSIGNED_SHORT, 2};
    case ref::FramebufferFormat::RGBA16F:
      return {GL_HALF_FLOAT, 2};
    case ref::FramebufferFormat::RGBA32F:
      return {GL_FLOAT, 4};
    case ref::FramebufferFormat::RGBA12:
      break;
  }
  throw GlUnsupported("GL has no " + std::string(ref::name(format)) + " colour format");
}

}  // namespace voxref::gpu
