// A time-varying scene: the data series, the encoding, the decoder, what is rendered (decode-only
// planes or a composited frame) and the sample points. JSON form for `voxref render` (strict, see
// json_reader.h); built-in cases carry theirs.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/framework/json_reader.h"
#include "reference/common/plane_frame.h"
#include "reference/timevarying/decoder_variants.h"

namespace voxref::conf {

struct TimeVaryingScene {
  // "blobs" (driftingBlobs), "plume" (dischargePlume), "plume_sparseness" (bisection on the gain),
  // "empty_noise_full" (3 steps: all 0, noise without 0, all 255)
  std::string data = "blobs";
  int side = 32, steps = 6;
  double sparseness = 0.9965;  // plume_sparseness only
  double plumeGain = 4000.0;   // plume only
  std::string transfer = "gray";
  ref::TimeVaryingOptions encoding;
  ref::DecoderVariant decoder = ref::DecoderVariant::TexelFetch;
  bool composite = false;  // false: every plane decoded and read back separately
  // Sample points: "voxel_centres", "voxel_faces", "block_faces", "coordinate_one" (explicit
  // frames on the volume's lattice), "face_ulps" (x 2^-24 either side of every voxel face:
  // ref::straddlingFrame) or "orbit" (azimuth 30, elevation 20).
  std::string frame = "voxel_centres";
  int width = 64, height = 64, planes = 48;  // orbit frames only
  std::vector<int> onlySteps;                // empty: every step
};

TimeVaryingScene parseTimeVaryingScene(const nlohmann::json& j);  // throws JsonFieldError
nlohmann::json toJson(const TimeVaryingScene& scene);
std::string seriesKey(const TimeVaryingScene& scene);  // scenes with equal keys share their data
ref::TimeSeries makeSeries(const TimeVaryingScene& scene);
ref::PlaneFrame makeFrame(const TimeVaryingScene& scene, const ref::TimeVaryingLayout& layout);
std::vector<int> stepsOf(const TimeVaryingScene& scene);

}  // namespace voxref::conf
