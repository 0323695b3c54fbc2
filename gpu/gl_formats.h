// voxref's formats as GL enums, and the packing of stored codes into upload bytes.
#pragma once

#include <GL/glcorearb.h>

#include <cstdint>
#include <vector>

#include "reference/common/gl_state.h"

namespace voxref::gpu {

struct TexelUpload {
  GLint internalFormat;
  GLenum format;
  GLenum type;
};
TexelUpload texelUpload(ref::TexelFormat format);

// Bytes to hand to glTexImage3D: the codes in the format's type (RGBA8 puts the code in red and
// zero in green, blue and alpha).
std::vector<unsigned char> packTexels(ref::TexelFormat format, const std::vector<std::uint32_t>& codes);

GLint glWrap(ref::Wrap wrap);
GLenum glBlendEquationOf(ref::BlendEquation e);

// Colour renderbuffer formats (not RGBA12, which GL lacks).
GLenum colorInternalFormat(ref::FramebufferFormat format);

// The type that reads a format's red channel back unchanged: GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT,
// GL_HALF_FLOAT, GL_FLOAT, and its size.
struct ReadbackType {
  GLenum type;
  std::size_t bytes;
};
ReadbackType readbackType(ref::FramebufferFormat format);

}  // namespace voxref::gpu
