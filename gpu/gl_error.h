// Exceptions of the GL layer. Every GL failure surfaces as one of these, with a message that
// names what was being done; nothing is retried or silently ignored.
#pragma once

#include <GL/glcorearb.h>

#include <stdexcept>
#include <string>

namespace voxref::gpu {

struct GlApi;

// No usable GL: the library, the context or an entry point is missing.
class GlUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The context works but lacks what a case needs (texture size, format, GLSL version). The
// conformance runner turns this into a skip with the message as the reason.
class GlUnsupported : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// glGetError reported an error, or a framebuffer is incomplete.
class GlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A shader failed to compile or a program to link; carries the driver's info log, whose line
// numbers are those of the source file (the prelude voxref adds ends with #line 1).
class ShaderError : public std::runtime_error {
 public:
  ShaderError(const std::string& what, std::string infoLog)
      : std::runtime_error(what + ":\n" + infoLog), log_(std::move(infoLog)) {}
  const std::string& infoLog() const { return log_; }

 private:
  std::string log_;
};

// Throws GlError "<what>: GL_INVALID_ENUM" etc. if glGetError reports an error.
void checkGl(const GlApi& gl, const std::string& what);

std::string glErrorName(GLenum error);

}  // namespace voxref::gpu
