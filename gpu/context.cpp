#include "gpu/context.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "gpu/context_backends.h"
#include "gpu/gl_error.h"

namespace voxref::gpu {

std::string_view name(Driver d) {
  switch (d) {
    case Driver::Llvmpipe:
      return "llvmpipe";
    case Driver::Softpipe:
      return "softpipe";
    case Driver::Egl:
      return "egl";
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

void preloadDriverLibrary(Driver driver) {
  if (driver != Driver::Egl) loadOsmesaLibrary();
}

std::vector<std::pair<std::string, std::string>> environmentPins() {
  std::vector<std::pair<std::string, std::string>> pins;
  static constexpr const char* kAlways[] = {
      "GALLIUM_DRIVER", "GALLIVM_PERF", "LP_NATIVE_VECTOR_WIDTH", "LP_PERF", "GALLIUM_OVERRIDE_CPU_CAPS",
      "EGL_PLATFORM"};
  for (const char* var : kAlways) {
    const char* v = std::getenv(var);
    pins.emplace_back(var, v ? v : "(unset)");
  }
  // Every other variable that is set and can change which driver, loader, ICD or code path runs:
  // Mesa's and the GL and EGL loaders' (MESA_LOADER_DRIVER_OVERRIDE, LIBGL_ALWAYS_SOFTWARE,
  // MESA_GL_VERSION_OVERRIDE, __EGL_VENDOR_LIBRARY_FILENAMES ...), the Vulkan loader's for zink
  // (VK_ICD_FILENAMES, VK_DRIVER_FILES ...), the drivers' own debug settings, the dynamic linker's.
  static constexpr const char* kPrefixes[] = {
      "MESA_",   "LIBGL_",         "GALLIUM_", "GALLIVM_", "LP_",    "SOFTPIPE_", "ZINK_",           "LVP_",
      "NIR_",    "GLSL_",          "VK_",      "EGL_",     "__EGL_", "__GLX_",    "__GL_",           "DRI_",
      "RADV_",   "AMD_",           "ANV_",     "INTEL_",   "NV_",    "NOUVEAU_",  "LD_LIBRARY_PATH", "LD_PRELOAD",
      "DISPLAY", "WAYLAND_DISPLAY"};
  std::vector<std::pair<std::string, std::string>> more;
  for (char** e = environ; e && *e; ++e) {
    const std::string entry(*e);
    const std::size_t eq = entry.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = entry.substr(0, eq);
    bool relevant = false;
    for (const char* p : kPrefixes) relevant = relevant || key.rfind(p, 0) == 0;
    for (const char* a : kAlways) relevant = relevant && key != a;
    if (relevant) more.emplace_back(key, entry.substr(eq + 1));
  }
  std::sort(more.begin(), more.end());
  pins.insert(pins.end(), more.begin(), more.end());
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
