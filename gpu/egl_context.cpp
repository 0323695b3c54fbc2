// Headless EGL contexts for real GPUs (EGL_EXT_platform_device) or Mesa's surfaceless platform.
//
// libEGL is loaded at run time, so a machine without it can still run the OSMesa drivers; its
// absence is reported as GlUnavailable when --driver egl is asked for. The platform used is
// recorded in ContextInfo::api (never chosen silently): EGL_PLATFORM=device|surfaceless selects
// one; by default the first EGL device is used, and the surfaceless platform when the client
// offers no device platform.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>

#include <cstdlib>
#include <string>
#include <string_view>

#include "gpu/context_backends.h"
#include "gpu/gl_error.h"

namespace voxref::gpu {
namespace {

struct EglLibrary {
  void* handle = nullptr;
  PFNEGLGETPROCADDRESSPROC getProcAddress = nullptr;
  template <class Fn>
  Fn get(const char* fn) const {
    void* p = dlsym(handle, fn);
    if (!p) p = reinterpret_cast<void*>(getProcAddress(fn));
    if (!p) throw GlUnavailable(std::string("libEGL does not provide ") + fn);
    return reinterpret_cast<Fn>(p);
  }
};

class EglContext final : public Context {
 public:
  EglContext() {
    lib_.handle = dlopen("libEGL.so.1", RTLD_NOW | RTLD_LOCAL);
    if (!lib_.handle) throw GlUnavailable(std::string("cannot load libEGL.so.1: ") + dlerror());
    lib_.getProcAddress = reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(dlsym(lib_.handle, "eglGetProcAddress"));
    if (!lib_.getProcAddress) throw GlUnavailable("libEGL.so.1 has no eglGetProcAddress");
    auto queryString = lib_.get<PFNEGLQUERYSTRINGPROC>("eglQueryString");
    const char* clientExt = queryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    const std::string_view ext = clientExt ? clientExt : "";
    auto has = [&](std::string_view e) { return ext.find(e) != std::string_view::npos; };
    auto getPlatformDisplay = lib_.get<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
    const char* env = std::getenv("EGL_PLATFORM");
    const std::string wanted = env ? env : (has("EGL_EXT_platform_device") ? "device" : "surfaceless");
    std::string platform;
    if (wanted == "device") {
      if (!has("EGL_EXT_platform_device")) throw GlUnavailable("EGL has no EGL_EXT_platform_device");
      auto queryDevices = lib_.get<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
      EGLDeviceEXT device = nullptr;
      EGLint count = 0;
      if (!queryDevices(1, &device, &count) || count < 1) throw GlUnavailable("EGL reports no devices");
      display_ = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
      platform = "device";
    } else if (wanted == "surfaceless") {
      if (!has("EGL_MESA_platform_surfaceless")) throw GlUnavailable("EGL has no EGL_MESA_platform_surfaceless");
      display_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      platform = "surfaceless";
    } else {
      throw GlUnavailable("EGL_PLATFORM=" + wanted + " is not supported (device or surfaceless)");
    }
    if (display_ == EGL_NO_DISPLAY)
      throw GlUnavailable("eglGetPlatformDisplay failed on the " + platform + " platform");
    auto initialize = lib_.get<PFNEGLINITIALIZEPROC>("eglInitialize");
    terminate_ = lib_.get<PFNEGLTERMINATEPROC>("eglTerminate");
    if (!initialize(display_, nullptr, nullptr))
      throw GlUnavailable("eglInitialize failed on the " + platform + " platform");
    if (!lib_.get<PFNEGLBINDAPIPROC>("eglBindAPI")(EGL_OPENGL_API))
      throw GlUnavailable("EGL cannot bind the OpenGL API");
    auto createContext = lib_.get<PFNEGLCREATECONTEXTPROC>("eglCreateContext");
    destroyContext_ = lib_.get<PFNEGLDESTROYCONTEXTPROC>("eglDestroyContext");
    for (const auto& [major, minor] : {std::pair{4, 5}, std::pair{3, 3}}) {
      const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                major,
                                EGL_CONTEXT_MINOR_VERSION,
                                minor,
                                EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                EGL_NONE};
      context_ = createContext(display_, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
      if (context_ != EGL_NO_CONTEXT) break;
    }
    if (context_ == EGL_NO_CONTEXT) throw GlUnavailable("EGL could not create a 4.5 or 3.3 core context");
    if (!lib_.get<PFNEGLMAKECURRENTPROC>("eglMakeCurrent")(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_))
      throw GlUnavailable("eglMakeCurrent without a surface failed (EGL_KHR_surfaceless_context missing?)");
    initialise([this](const char* fn) { return reinterpret_cast<void*>(lib_.getProcAddress(fn)); }, Driver::Egl,
               "EGL (" + platform + ")");
  }
  ~EglContext() override {
    if (context_ != EGL_NO_CONTEXT) destroyContext_(display_, context_);
    if (display_ != EGL_NO_DISPLAY) terminate_(display_);
  }

 private:
  EglLibrary lib_;
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  PFNEGLDESTROYCONTEXTPROC destroyContext_ = nullptr;
  PFNEGLTERMINATEPROC terminate_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> createEglContext() { return std::make_unique<EglContext>(); }

}  // namespace voxref::gpu
