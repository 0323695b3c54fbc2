// GL contexts: OSMesa (llvmpipe or softpipe, here) and EGL (real GPUs, headless).
//
// A context is current on the creating thread for its whole life; voxref renders into its own
// framebuffer objects, never into a window. Creation throws GlUnavailable with the reason (no
// library, no display, wrong driver, version too low). OSMesa picks its gallium driver once per
// process from GALLIUM_DRIVER, so one process can hold contexts of one OSMesa driver only.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "gpu/gl_api.h"

namespace voxref::gpu {

enum class Driver { Llvmpipe, Softpipe, Egl };
std::string_view name(Driver d);
std::optional<Driver> parseDriver(std::string_view s);

struct ContextInfo {
  Driver driver = Driver::Llvmpipe;
  std::string api;  // "OSMesa" or "EGL (<platform>)"
  std::string renderer, version, vendor, glslVersion;
  int glMajor = 0, glMinor = 0;
  int glslNumber = 0;        // e.g. 450, 330
  int max3DTextureSize = 0;  // GL_MAX_3D_TEXTURE_SIZE
  int maxRenderbufferSize = 0;
  bool supportsPrecise() const { return glslNumber >= 400; }  // `precise` needs GLSL 4.00
};

class Context {
 public:
  virtual ~Context() = default;
  const GlApi& gl() const { return gl_; }
  const ContextInfo& info() const { return info_; }

 protected:
  void initialise(const GetProcAddress& getProcAddress, Driver driver, std::string api);

 private:
  GlApi gl_;
  ContextInfo info_;
};

// The drivers' required versions: 4.5 core for llvmpipe, 3.3 core for softpipe (its maximum),
// the highest of 4.5 / 3.3 core for EGL.
std::unique_ptr<Context> createContext(Driver driver);

// Loads the driver's library (libOSMesa and what it links: LLVM, the gallium drivers) into this
// process without creating a context, screen or thread, so that processes forked afterwards share
// the loaded, relocated library instead of each loading it again (symbol binding was about 80 % of
// a case process's start-up). Throws GlUnavailable as createContext would; does nothing for EGL,
// whose driver is chosen and loaded only by eglInitialize.
void preloadDriverLibrary(Driver driver);

// Environment variables that change which driver runs or what it computes (docs/precision.md),
// so that a report says how to reproduce its run: GALLIUM_DRIVER, GALLIVM_PERF,
// LP_NATIVE_VECTOR_WIDTH, LP_PERF, GALLIUM_OVERRIDE_CPU_CAPS and EGL_PLATFORM always (value or
// "(unset)"), then, sorted, every other set variable of Mesa, the GL, EGL and Vulkan loaders and
// the drivers (prefixes MESA_, LIBGL_, GALLIUM_, GALLIVM_, LP_, SOFTPIPE_, ZINK_, LVP_, NIR_,
// GLSL_, VK_, EGL_, __EGL_, __GLX_, __GL_, DRI_, RADV_, AMD_, ANV_, INTEL_, NV_, NOUVEAU_), and
// LD_LIBRARY_PATH, LD_PRELOAD, DISPLAY, WAYLAND_DISPLAY.
std::vector<std::pair<std::string, std::string>> environmentPins();

}  // namespace voxref::gpu
