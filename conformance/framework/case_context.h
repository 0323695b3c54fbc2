// What a case gets from the runner: the GL context of the run, the precision profile (or none,
// for a driver voxref has no profile for), where to write images, and a small cache that lets
// cases differing only in shading share their rendered planes.
#pragma once

#include <filesystem>
#include <functional>
#include <list>
#include <memory>
#include <string>
#include <utility>

#include "emulation/measured_arithmetic.h"
#include "emulation/profile.h"
#include "gpu/context.h"
#include "gpu/shader_override.h"

namespace voxref::conf {

class CaseContext {
 public:
  CaseContext(gpu::Context* gl, const emu::PrecisionProfile* profile, std::filesystem::path outDir, int threads,
              bool writeAllImages, emu::MeasuredArithmetic measured = {})
      : gl_(gl),
        profile_(profile),
        outDir_(std::move(outDir)),
        threads_(threads),
        allImages_(writeAllImages),
        measured_(measured) {}

  gpu::Context* gl() const { return gl_; }
  const emu::PrecisionProfile* profile() const { return profile_; }  // nullptr: envelope only
  // What the envelopes may rely on besides the spec (probe/profile_choice.h, envelopeArithmetic).
  const emu::MeasuredArithmetic& measured() const { return measured_; }
  const std::filesystem::path& outDir() const { return outDir_; }
  int threads() const { return threads_; }
  bool writeAllImages() const { return allImages_; }
  // A user's shader in place of a built-in stage (voxref check-shader), or nullptr. Cases hand it
  // to the GL passes, which use it only for the stage it names; it must outlive the context.
  const gpu::ShaderOverride* shaderOverride() const { return shaderOverride_; }
  void setShaderOverride(const gpu::ShaderOverride* shader) { shaderOverride_ = shader; }

  // The value cached under `key`, made by `make` on a miss. Keeps the last few entries.
  template <class T>
  std::shared_ptr<T> cached(const std::string& key, const std::function<std::shared_ptr<T>()>& make) {
    for (auto it = cache_.begin(); it != cache_.end(); ++it)
      if (it->first == key) {
        cache_.splice(cache_.begin(), cache_, it);
        return std::static_pointer_cast<T>(cache_.front().second);
      }
    std::shared_ptr<T> value = make();
    cache_.emplace_front(key, value);
    if (cache_.size() > kCacheEntries) cache_.pop_back();
    return value;
  }

 private:
  static constexpr std::size_t kCacheEntries = 4;
  gpu::Context* gl_;
  const emu::PrecisionProfile* profile_;
  std::filesystem::path outDir_;
  int threads_;
  bool allImages_;
  emu::MeasuredArithmetic measured_;
  const gpu::ShaderOverride* shaderOverride_ = nullptr;
  std::list<std::pair<std::string, std::shared_ptr<void>>> cache_;
};

}  // namespace voxref::conf
