// OSMesa contexts on Mesa's gallium software drivers (llvmpipe, softpipe).
//
// glcorearb.h (through context.h) must come before osmesa.h: osmesa.h pulls in GL/gl.h, whose
// GL_VERSION_1_1 guard would hide glcorearb.h's GL 1.x function-pointer types.
#include "gpu/context.h"
#include "gpu/context_backends.h"
#include "gpu/gl_error.h"

#include <GL/osmesa.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace voxref::gpu {
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
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,  // RGBA, not BGRA: BGRA enables llvmpipe's 8-bit linear path
                           OSMESA_DEPTH_BITS, 0, OSMESA_STENCIL_BITS, 0, OSMESA_ACCUM_BITS, 0,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, major,
                           OSMESA_CONTEXT_MINOR_VERSION, minor, 0};
    ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx_)
      throw GlUnavailable("OSMesa could not create a " + std::to_string(major) + "." + std::to_string(minor) +
                          " core context on " + wanted);
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
      OSMesaDestroyContext(ctx_);
      throw GlUnavailable("OSMesaMakeCurrent failed on " + wanted);
    }
    initialise([](const char* fn) { return reinterpret_cast<void*>(OSMesaGetProcAddress(fn)); }, driver, "OSMesa");
    if (info().renderer.rfind(wanted, 0) != 0) {
      const std::string got = info().renderer;
      OSMesaDestroyContext(ctx_);
      throw GlUnavailable("asked OSMesa for " + wanted + ", got GL_RENDERER '" + got + "'");
    }
  }
  ~OsmesaContext() override { OSMesaDestroyContext(ctx_); }

 private:
  std::vector<unsigned char> buffer_ = std::vector<unsigned char>(4);
  OSMesaContext ctx_ = nullptr;
};

}  // namespace

std::unique_ptr<Context> createOsmesaContext(Driver driver) { return std::make_unique<OsmesaContext>(driver); }

}  // namespace voxref::gpu
