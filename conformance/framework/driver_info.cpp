#include "conformance/framework/driver_info.h"

#include <cstdlib>
#include <stdexcept>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#endif

namespace voxref::conf {

CpuFlags detectCpuFlags() {
  CpuFlags f;
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();
  f.ssse3 = __builtin_cpu_supports("ssse3");
  f.sse4_1 = __builtin_cpu_supports("sse4.1");
  f.avx2 = __builtin_cpu_supports("avx2");
  f.fma = __builtin_cpu_supports("fma");
  // F16C: CPUID leaf 1, ECX bit 29 (Intel SDM vol. 2A, CPUID), usable where the OS saves the AVX
  // state; read directly, as clang has no "f16c" for __builtin_cpu_supports.
  unsigned a = 0, b = 0, c = 0, d = 0;
  f.f16c = __get_cpuid(1, &a, &b, &c, &d) && (c & (1u << 29)) && __builtin_cpu_supports("avx");
#endif
  return f;
}

const emu::PrecisionProfile* chooseProfile(const std::string& choice, const gpu::ContextInfo& info, std::string& how) {
  if (choice == "envelope") {  // docs/design.md: `envelope` is the spec model, no driver's arithmetic
    how = "named on the command line: envelope, the spec model alone; judged by the envelope oracle alone";
    return nullptr;
  }
  if (choice != "auto") {
    const emu::PrecisionProfile* p = emu::findProfile(choice);
    if (!p) {
      std::string known;
      for (const auto& k : emu::knownProfiles()) known += (known.empty() ? "" : ", ") + std::string(k.name);
      throw std::invalid_argument("unknown profile '" + choice + "' (known: auto, envelope, " + known + ")");
    }
    how = "named on the command line";
    return p;
  }
  auto env = [](const char* v) {
    const char* s = std::getenv(v);
    return std::string(s ? s : "");
  };
  const emu::PrecisionProfile* p =
      emu::autoProfile(info.renderer, env("GALLIVM_PERF"), env("GALLIUM_OVERRIDE_CPU_CAPS"), detectCpuFlags().fma);
  how = p ? "auto: GL_RENDERER '" + info.renderer + "', GALLIVM_PERF='" + env("GALLIVM_PERF") +
                "', GALLIUM_OVERRIDE_CPU_CAPS='" + env("GALLIUM_OVERRIDE_CPU_CAPS") + "', CPU FMA " +
                (detectCpuFlags().fma ? "yes" : "no")
          : "auto: no profile for GL_RENDERER '" + info.renderer + "'; judged by the envelope oracle alone";
  return p;
}

nlohmann::json driverJson(const gpu::ContextInfo& info, const emu::PrecisionProfile* profile, const std::string& how) {
  const CpuFlags cpu = detectCpuFlags();
  nlohmann::json pins = nlohmann::json::object();
  for (const auto& [k, v] : gpu::environmentPins()) pins[k] = v;
  nlohmann::json j = {
      {"driver", gpu::name(info.driver)},
      {"api", info.api},
      {"renderer", info.renderer},
      {"version", info.version},
      {"vendor", info.vendor},
      {"glsl_version", info.glslVersion},
      {"max_3d_texture_size", info.max3DTextureSize},
      {"environment", pins},
      {"cpu_flags",
       {{"ssse3", cpu.ssse3}, {"sse4_1", cpu.sse4_1}, {"avx2", cpu.avx2}, {"fma", cpu.fma}, {"f16c", cpu.f16c}}},
  };
  j["profile"] = profile ? nlohmann::json{{"name", profile->name},
                                          {"summary", profile->summary},
                                          {"environment", profile->environment},
                                          {"chosen", how}}
                         : nlohmann::json{{"name", nullptr}, {"chosen", how}};
  return j;
}

}  // namespace voxref::conf
