// A sparse-grid scene: the data, the sparse grid, the GL state of the paper's hardware method,
// the camera and the image, as plain data with a JSON form (conformance/modules/sparsegrid/SCENE.md).
//
// Parsing is strict: unknown keys, wrong types and out-of-range values throw SceneError naming
// the field and what was expected. Safe on untrusted input.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "conformance/framework/json_reader.h"

#include "reference/common/fields.h"
#include "reference/common/gl_state.h"
#include "reference/common/plane_frame.h"
#include "reference/common/plane_shading.h"
#include "reference/sparsegrid/combination_textures.h"
#include "reference/sparsegrid/subspaces.h"

namespace voxref::conf {

using SceneError = JsonFieldError;

struct DataSource {
  std::string field = "gaussian_blobs";  // an analytic field (reference/common/fields.h), or
  std::filesystem::path volume;          // a raw uint8 volume file (.raw or .raw.gz) ...
  ref::Dims3 volumeDims{0, 0, 0};        // ... with these dimensions
  bool isVolume() const { return !volume.empty(); }
};

struct Camera {
  double azimuth = 30.0, elevation = 20.0;  // orbitFrame
  // Or an explicit frame (plane_frame.h); all four set together.
  std::optional<glm::dvec3> origin, dx, dy, dz;
};

struct SparseGridScene {
  DataSource data;
  ref::SparseGridSpec grid{6, true};
  ref::CombinationTextureOptions textures;  // format, sizing, scaling
  ref::SamplerState sampler;
  ref::FramebufferFormat framebuffer = ref::FramebufferFormat::RGBA8;
  bool flushEachPass = false;
  std::vector<int> passOrder;  // a permutation of the method's passes (empty: the paper's order)
  ref::ShadingParams shading;
  Camera camera;
  int width = 48, height = 48, planes = 32;
};

SparseGridScene parseSparseGridScene(const nlohmann::json& j);  // throws SceneError
nlohmann::json toJson(const SparseGridScene& scene);

// The scene without its shading: scenes that differ only in render mode share their planes.
std::string planeKey(const SparseGridScene& scene);

// The field the scene samples (reads the volume file; io::IoError on a bad file).
ref::Field loadField(const DataSource& data);
ref::PlaneFrame makeFrame(const SparseGridScene& scene);  // SceneError if not float32-exact

}  // namespace voxref::conf
