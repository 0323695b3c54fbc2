#include "gpu/gl_error.h"

#include "gpu/gl_api.h"

namespace voxref::gpu {

std::string glErrorName(GLenum error) {
  switch (error) {
    case GL_NO_ERROR:
      return "GL_NO_ERROR";
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    case GL_STACK_UNDERFLOW:
      return "GL_STACK_UNDERFLOW";
    case GL_STACK_OVERFLOW:
      return "GL_STACK_OVERFLOW";
  }
  return "GL error 0x" + [error] {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%04x", error);
    return std::string(buf);
  }();
}

void checkGl(const GlApi& gl, const std::string& what) {
  const GLenum first = gl.GetError();
  if (first == GL_NO_ERROR) return;
  std::string message = what + ": " + glErrorName(first);
  // Drain the queue so that the next check reports only new errors.
  for (GLenum e = gl.GetError(); e != GL_NO_ERROR; e = gl.GetError()) message += ", " + glErrorName(e);
  throw GlError(message);
}

}  // namespace voxref::gpu
