// libFuzzer target: the scene JSON parsers on arbitrary bytes: the sparse-grid scene
// (conformance/modules/sparsegrid/sparsegrid_scene.h, conformance/modules/sparsegrid/SCENE.md), the time-varying scene
// (conformance/modules/timevarying/timevarying_scene.h), both read by `voxref render --scene FILE`, and
// the isosurface scene (conformance/modules/iso/iso_scene.h), read from fixture manifests. The bytes are
// parsed as JSON with nlohmann (an exception there ends the run: that is nlohmann's contract, not
// ours; note that it is a parse_error or, for a number beyond double's range, an out_of_range, which
// `voxref render` once let through) and the document goes to all three parsers.
//
// Contract under test:
// - parseSparseGridScene throws only SceneError (= JsonFieldError), parseTimeVaryingScene only
//   JsonFieldError, isoSceneFromJson only JsonFieldError (a missing, unknown or mistyped key, a
//   number out of range); nothing else escapes, nothing reads out of bounds
//   (ASan), no undefined behaviour (UBSan: a float converted into an int it does not fit is one);
// - a scene a parser accepts writes back (toJson, as text) into a document the same parser
//   accepts and that gives the same scene again (toJson of both equal);
// - what the callers do next with an accepted scene does not fail otherwise: sparse-grid
//   makeFrame throws only SceneError, planeKey; time-varying stepsOf, makeFrame (std::invalid_argument
//   for a frame that is not float32-exact).
// Size cap: makeFrame is called only for frames of at most 2^16 samples (width x height x
// planes, or side^3 for the voxel-lattice frames): explicit frames off the lattice are checked
// sample by sample, which is milliseconds per run above that; the parsers themselves are never
// skipped.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "conformance/modules/iso/iso_scene.h"
#include "conformance/modules/sparsegrid/sparsegrid_scene.h"
#include "conformance/modules/timevarying/timevarying_scene.h"

namespace {

using namespace voxref;
using nlohmann::json;

[[noreturn]] void violated(const char* parser, const std::string& what) {
  std::fprintf(stderr, "contract violated (%s): %s\n", parser, what.c_str());
  std::abort();
}

// toJson of the scene, through text, parses again into the same scene.
template <class Parse, class Scene>
void roundTrip(const char* parser, Parse parse, const Scene& scene) {
  const json written = conf::toJson(scene);
  json back;
  try {
    back = conf::toJson(parse(json::parse(written.dump())));
  } catch (const std::exception& e) {
    violated(parser, "the scene written back is refused: " + std::string(e.what()) + "\n" + written.dump());
  }
  if (back != written)
    violated(parser, "the scene written back reads as another scene:\n" + written.dump() + "\n" + back.dump());
}

void sparseGrid(const json& j) {
  conf::SparseGridScene s;
  try {
    s = conf::parseSparseGridScene(j);
  } catch (const conf::SceneError&) {
    return;
  }
  roundTrip("sparsegrid", conf::parseSparseGridScene, s);
  (void)conf::planeKey(s);
  if (static_cast<std::uint64_t>(s.width) * s.height * s.planes > (1u << 16)) return;
  try {
    (void)conf::makeFrame(s);
  } catch (const conf::SceneError&) {
  }
}

void timeVarying(const json& j) {
  conf::TimeVaryingScene s;
  try {
    s = conf::parseTimeVaryingScene(j);
  } catch (const conf::JsonFieldError&) {
    return;
  }
  roundTrip("timevarying", conf::parseTimeVaryingScene, s);
  (void)conf::seriesKey(s);
  (void)conf::stepsOf(s);
  const std::uint64_t samples = s.frame == "orbit" ? static_cast<std::uint64_t>(s.width) * s.height * s.planes
                                                   : static_cast<std::uint64_t>(s.side) * s.side * s.side;
  if (samples > (1u << 16) || s.encoding.level >= std::countr_zero(static_cast<unsigned>(s.side))) return;
  ref::TimeVaryingLayout layout;  // what makeFrame reads of the encoder's layout
  layout.side = s.side;
  layout.cells = 1 << s.encoding.level;
  layout.blockSide = s.side / layout.cells;
  try {
    (void)conf::makeFrame(s, layout);
  } catch (const std::invalid_argument&) {
  }
}

void iso(const json& j) {
  conf::IsoScene s;
  try {
    s = conf::isoSceneFromJson(j);
  } catch (const conf::JsonFieldError&) {
    return;
  }
  roundTrip("iso", conf::isoSceneFromJson, s);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  json j;
  try {
    j = json::parse(data, data + size);
  } catch (const json::exception&) {  // parse_error, or out_of_range for a number beyond double
    return 0;
  }
  sparseGrid(j);
  timeVarying(j);
  iso(j);
  return 0;
}
