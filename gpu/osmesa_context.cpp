// OSMesa contexts on Mesa's gallium software drivers (llvmpipe, softpipe).
//
// libOSMesa is loaded at run time (dlopen), not linked: commands that need no GL (list, encode,
// decode, info, fixtures, bench tables without GL) run on a machine without it, and a missing or
// broken library is a GlUnavailable naming the library and the loader's error instead of the
// dynamic loader refusing to start voxref. VOXREF_OSMESA names another library to load (a Mesa
// built from source, say); the default is libOSMesa.so.8 (Debian's libosmesa6).
//
// glcorearb.h (through context.h) must come before osmesa.h: osmesa.h pulls in GL/gl.h, whose
// GL_VERSION_1_1 guard would hide glcorearb.h's GL 1.x function-pointer types.
#include "gpu/context.h"
#include "gpu/context_backends.h"
#include "gpu/gl_error.h"

#include <GL/osmesa.h>
#include <dlfcn.h>

#include <cstdlib>
#include <string>
#include <type_traits>
#include <vector>

namespace voxref::gpu {
namespace {

// The four entry points voxref uses, from the library loaded once per process.
struct OsmesaLibrary {
  decltype(&OSMesaCreateContextAttribs) createContextAttribs = nullptr;
  decltype(&OSMesaMakeCurrent) makeCurrent = nullptr;
  decltype(&OSMesaDestroyContext) destroyContext = nullptr;
  decltype(&OSMesaGetProcAddress) getProcAddress = nullptr;
};

const OsmesaLibrary& osmesa() {
  static const OsmesaLibrary lib = [] {
    const char* env = std::getenv("VOXREF_OSMESA");
    const std::string path = env && *env ? env : "libOSMesa.so.8";
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle)
      throw GlUnavailable("cannot load the OSMesa library " + path + ": " + dlerror() +
                          (env ? " (VOXREF_OSMESA names it)"
                               : " (Debian: apt-get install libosmesa6; or set VOXREF_OSMESA to a libOSMesa)"));
    OsmesaLibrary l;
    auto get = [&](auto& slot, const char* fn) {
      slot = reinterpret_cast<std::remove_reference_t<decltype(slot)>>(dlsym(handle, fn));
      if (!slot) throw GlUnavailable("the OSMesa library " + path + " has no " + fn);
    };
    get(l.createContextAttribs, "OSMesaCreateContextAttribs");
    get(l.makeCurrent, "OSMesaMakeCurrent");
    get(l.destroyContext, "OSMesaDestroyContext");
    get(l.getProcAddress, "OSMesaGetProcAddress");
    return l;  // the handle stays open for the life of the process
  }();
  return lib;
}

}  // namespace

void loadOsmesaLibrary() { osmesa(); }

namespace {

class OsmesaContext final : public Context {
 public:
  explicit OsmesaContext(Driver driver) {
    const std::string wanted(name(driver));
    // OSMesa creates its gallium screen once per process from GALLIUM_DRIVER.
    if (const char* env = std::getenv("GALLIUM_DRIVER"); env && wanted != env)
      throw GlUnavailable("GALLIUM_DRIVER=" + std::string(env) + " in the environment contradicts --driver " + wanted);
    setenv("GALLIUM_DRIVER", wanted.c_str(), 1);
    const int major = driver == Driver::Softpipe ? 3 : 4, minor = driver == Driver::Softpipe ? 3 : 5;
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,  // RGBA, not BGRA: BGRA enables llvmpipe's 8-bit linear path
                           OSMESA_DEPTH_BITS,
                           0,
                           OSMESA_STENCIL_BITS,
                           0,
                           OSMESA_ACCUM_BITS,
                           0,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           major,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           minor,
                           0};
    ctx_ = lib_.createContextAttribs(attribs, nullptr);
    if (!ctx_)
      throw GlUnavailable("OSMesa could not create a " + std::to_string(major) + "." + std::to_string(minor) +
                          " core context on " + wanted);
    if (!lib_.makeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      lib_.destroyContext(ctx_);
      throw GlUnavailable("OSMesaMakeCurrent failed on " + wanted);
    }
    initialise([this](const char* fn) { return reinterpret_cast<void*>(lib_.getProcAddress(fn)); }, driver, "OSMesa");
    if (info().renderer.rfind(wanted, 0) != 0) {
      const std::string got = info().renderer;
      lib_.destroyContext(ctx_);
      throw GlUnavailable("asked OSMesa for " + wanted + ", got GL_RENDERER '" + got + "'");
    }
  }
  ~OsmesaContext() override { lib_.destroyContext(ctx_); }

 private:
  const OsmesaLibrary& lib_ = osmesa();
  std::vector<unsigned char> buffer_ = std::vector<unsigned char>(4);
  OSMesaContext ctx_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> createOsmesaContext(Driver driver) { return std::make_unique<OsmesaContext>(driver); }

}  // namespace voxref::gpu
