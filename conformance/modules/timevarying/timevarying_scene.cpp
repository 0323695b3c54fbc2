#include "conformance/modules/timevarying/timevarying_scene.h"

#include "reference/timevarying/plume.h"

namespace voxref::conf {

TimeVaryingScene parseTimeVaryingScene(const nlohmann::json& j) {
  TimeVaryingScene s;
  JsonObjectReader r(j, "");
  if (r.get<std::string>("system", "timevarying") != "timevarying")
    throw JsonFieldError("system: expected 'timevarying'");
  s.data = r.get<std::string>("data", s.data);
  if (s.data != "blobs" && s.data != "plume" && s.data != "plume_sparseness" && s.data != "empty_noise_full")
    throw JsonFieldError("data: '" + s.data + "' is not one of blobs, plume, plume_sparseness, empty_noise_full");
  s.side = r.getInt("side", s.side, 8, 512);
  if ((s.side & (s.side - 1)) != 0) throw JsonFieldError("side: expected a power of two");
  s.steps = r.getInt("steps", s.steps, 1, 4096);
  s.sparseness = r.get<double>("sparseness", s.sparseness);
  s.plumeGain = r.get<double>("plume_gain", s.plumeGain);
  s.transfer = r.get<std::string>("transfer", s.transfer);
  try {
    (void)ref::transferFunction(s.transfer);
  } catch (const std::invalid_argument& e) {
    throw JsonFieldError(std::string("transfer: ") + e.what());
  }
  s.encoding.level = r.getInt("level", s.encoding.level, 1, 8);
  const std::string enc = r.get<std::string>("encoding", std::string(ref::name(s.encoding.encoding)));
  const auto e = ref::parseIndexEncoding(enc);
  if (!e)
    throw JsonFieldError("encoding: '" + enc +
                         "' is not one of normalized_rgba8, normalized_rgba16, normalized_float, block_rgba8");
  s.encoding.encoding = *e;
  const std::string policy = r.get<std::string>("alpha_one", "refine");
  if (policy != "refine" && policy != "paper") throw JsonFieldError("alpha_one: expected refine or paper");
  s.encoding.alphaOne = policy == "paper" ? ref::AlphaOnePolicy::Paper : ref::AlphaOnePolicy::Refine;
  s.encoding.paperLayout = r.get<bool>("paper_layout", false);
  s.encoding.hashBits = r.getInt("hash_bits", 64, 1, 64);
  const std::string dec = r.get<std::string>("decoder", std::string(ref::name(s.decoder)));
  const auto d = ref::parseDecoderVariant(dec);
  if (!d) throw JsonFieldError("decoder: '" + dec + "' is not one of literal, paper, texel_centre, texel_fetch");
  s.decoder = *d;
  s.composite = r.get<bool>("composite", false);
  s.frame = r.get<std::string>("frame", s.frame);
  if (s.frame != "voxel_centres" && s.frame != "voxel_faces" && s.frame != "face_ulps" && s.frame != "block_faces" &&
      s.frame != "coordinate_one" && s.frame != "orbit")
    throw JsonFieldError("frame: '" + s.frame +
                         "' is not one of voxel_centres, voxel_faces, face_ulps, block_faces, coordinate_one, orbit");
  readFrameExtents(r, s.width, s.height, s.planes);
  s.onlySteps = r.get<std::vector<int>>("only_steps", {});
  for (int t : s.onlySteps)
    if (t < 0 || t >= s.steps)
      throw JsonFieldError("only_steps: " + std::to_string(t) + " is outside 0.." + std::to_string(s.steps - 1));
  r.finish();
  return s;
}

nlohmann::json toJson(const TimeVaryingScene& s) {
  nlohmann::json j = {{"system", "timevarying"},
                      {"data", s.data},
                      {"side", s.side},
                      {"steps", s.steps},
                      {"transfer", s.transfer},
                      {"level", s.encoding.level},
                      {"encoding", ref::name(s.encoding.encoding)},
                      {"alpha_one", s.encoding.alphaOne == ref::AlphaOnePolicy::Paper ? "paper" : "refine"},
                      {"paper_layout", s.encoding.paperLayout},
                      {"hash_bits", s.encoding.hashBits},
                      {"decoder", ref::name(s.decoder)},
                      {"composite", s.composite},
                      {"frame", s.frame}};
  if (s.data == "plume_sparseness") j["sparseness"] = s.sparseness;
  if (s.data == "plume") j["plume_gain"] = s.plumeGain;
  if (s.frame == "orbit") {
    j["image"] = {s.width, s.height};
    j["planes"] = s.planes;
  }
  if (!s.onlySteps.empty()) j["only_steps"] = s.onlySteps;
  return j;
}

std::string seriesKey(const TimeVaryingScene& s) {
  return s.data + "/" + std::to_string(s.side) + "/" + std::to_string(s.steps) + "/" +
         (s.data == "plume_sparseness" ? std::to_string(s.sparseness)
          : s.data == "plume"          ? std::to_string(s.plumeGain)
                                       : "");
}

ref::TimeSeries makeSeries(const TimeVaryingScene& s) {
  if (s.data == "plume") return ref::dischargePlume({s.side, s.steps, s.plumeGain});
  if (s.data == "plume_sparseness") return ref::dischargePlumeWithSparseness({s.side, s.steps}, s.sparseness);
  if (s.data == "empty_noise_full") {  // step 0 empty, step 1 deterministic noise (no zero), step 2 full (255)
    ref::TimeSeries t;
    t.side = s.side;
    t.original = {s.side, s.side, s.side};
    const std::size_t n = static_cast<std::size_t>(s.side) * s.side * s.side;
    std::vector<std::uint8_t> noise(n);
    std::uint32_t x = 2463534242u;
    for (auto& v : noise) {
      x ^= x << 13, x ^= x >> 17, x ^= x << 5;  // xorshift32
      v = static_cast<std::uint8_t>(1 + x % 255);
    }
    t.steps = {std::vector<std::uint8_t>(n, 0), noise, std::vector<std::uint8_t>(n, 255)};
    return t;
  }
  return ref::driftingBlobs(s.side, s.steps);
}

ref::PlaneFrame makeFrame(const TimeVaryingScene& s, const ref::TimeVaryingLayout& layout) {
  const double h = 1.0 / s.side;
  const int n = s.side;
  if (s.frame == "voxel_centres") return ref::explicitFrame({0, 0, 0}, {h, 0, 0}, {0, h, 0}, {0, 0, h}, n, n, n);
  if (s.frame == "voxel_faces") return ref::explicitFrame(glm::dvec3(-h / 2), {h, 0, 0}, {0, h, 0}, {0, 0, h}, n, n, n);
  if (s.frame == "face_ulps")  // x 2^-24 either side of every voxel face (block faces among them), y at voxel centres
    return ref::straddlingFrame(0.0, h, n, {0, h, 0}, n, {0, h / 2, (n / 2 + 0.5) * h});
  if (s.frame == "block_faces") {
    const double b = h * layout.blockSide;  // x on the block faces 0, r, 2r, ...; y and z at voxel centres
    return ref::explicitFrame({-b / 2, 0, 0}, {b, 0, 0}, {0, h, 0}, {0, 0, h}, layout.cells, n, n);
  }
  if (s.frame == "coordinate_one")
    return ref::explicitFrame({1.0 - h / 2, 0, 0}, {h, 0, 0}, {0, h, 0}, {0, 0, h}, 1, n, n);
  return ref::orbitFrame(30.0, 20.0, s.width, s.height, s.planes);
}

std::vector<int> stepsOf(const TimeVaryingScene& s) {
  if (!s.onlySteps.empty()) return s.onlySteps;
  std::vector<int> all(static_cast<std::size_t>(s.steps));
  for (int t = 0; t < s.steps; ++t) all[static_cast<std::size_t>(t)] = t;
  return all;
}

}  // namespace voxref::conf
