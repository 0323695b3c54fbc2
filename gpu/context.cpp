#include "gpu/context.h"

#include <cstdio>
#include <cstdlib>

#include "gpu/gl_error.h"
#include "gpu/context_backends.h"

namespace voxref::gpu {

std::string_view name(Driver d) {
  switch (d) {
    case Driver::Llvmpipe: return "llvmpipe";
    case Driver::Softpipe: return "softpipe";
    case Driver::Egl: return "egl";
  }
  return "?";
}

std::optional<Driver> parseDriver(std::string_view s) {
  if (s == "llvmpipe") return Driver::Llvmpipe;
  if (s == "softpipe") return Driver::Softpipe;
  if (s == "egl") return Driver::Egl;
  return std::nullopt;
}

std::unique_ptr<Context> createContext(Driver driver) {
  return driver == Driver::Egl ? createEglContext() : createOsmesaContext(driver);
}

std::vector<std::pair<std::string, std::string>> environmentPins() {
  std::vector<std::pair<std::string, std::string>> pins;
  for (const char* var : {"GALLIUM_DRIVER", "GALLIVM_PERF", "LP_NATIVE_VECTOR_WIDTH", "LP_PERF", "GALLIUM_OVERRIDE_CPU_CAPS",
                          "EGL_PLATFORM"}) {
    const char* v = std::getenv(var);
    pins.emplace_back(var, v ? v : "(unset)");
  }
  return pins;
}

void Context::initialise(const GetProcAddress& getProcAddress, Driver driver, std::string api) {
  gl_ = loadGlApi(getProcAddress);
  auto str = [&](GLenum e) {
    const GLubyte* s = gl_.GetString(e);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
  };
  info_.driver = driver;
  info_.api = std::move(api);
  info_.renderer = str(GL_RENDERER);
  info_.version = str(GL_VERSION);
  info_.vendor = str(GL_VENDOR);
  info_.glslVersion = str(GL_SHADING_LANGUAGE_VERSION);
  gl_.GetIntegerv(GL_MAJOR_VERSION, &info_.glMajor);
  gl_.GetIntegerv(GL_MINOR_VERSION, &info_.glMinor);
  int major = 0, minor = 0;
  if (std::sscanf(info_.glslVersion.c_str(), "%d.%d", &major, &minor) == 2) info_.glslNumber = major * 100 + minor;
  gl_.GetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &info_.max3DTextureSize);
  gl_.GetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &info_.maxRenderbufferSize);
  checkGl(gl_, "querying the context");
  if (info_.glMajor * 10 + info_.glMinor < 33)
    throw GlUnavailable("the context offers GL " + info_.version + "; voxref needs 3.3 core or later");
}

}  // namespace voxref::gpu
