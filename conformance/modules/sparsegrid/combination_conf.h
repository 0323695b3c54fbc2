// Conformance of the paper's hardware method (Teitzel et al. 1999, section 6): one scene through
// the GL path, its emulation and the double reference, judged by the three oracles.
//
//   exact     GL read-back codes == emulation codes under the driver's profile, every sample of
//             every plane, bit for bit (and so the shaded images pixel for pixel);
//   envelope  every GL read-back value inside what any conforming implementation may produce
//             (emulation/combination_envelope.h): pass / quality warning / fail, with the allowed
//             interval of failing values;
//   ideal     distance of the GL (else emulated) planes and image from the double reference of
//             the same sample points: figures only, "what accuracy costs".
// Where the profile departs from the GL semantics (emulation/profile.h), the case also reports,
// per departure, how many samples it changes (findings).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "conformance/framework/case.h"
#include "conformance/framework/case_context.h"
#include "conformance/modules/sparsegrid/sparsegrid_scene.h"
#include "emulation/combination_emu.h"
#include "reference/common/framebuffer_codes.h"

namespace voxref::conf {

// Everything a scene's planes give, shared by the cases that differ only in render mode.
struct CombinationPlanes {
  SparseGridScene scene;
  ref::PlaneFrame frame;
  int gridCount = 0, positiveCount = 0;
  std::size_t passCount = 0, textureBytes = 0;
  int brickedGrids = 0;
  double readbackScale = 1.0;
  ref::SampleStack reference;
  std::optional<ref::CodePlanes> gl;
  std::string glNotRun;  // why gl is empty
  std::optional<emu::EmulatedPlanes> emulated;
  std::string emulationNotRun;
  std::vector<emu::Effect> simulated;  // what the emulation simulates for this scene
  std::vector<std::string> effects;    // their ids, for the report
  // Envelope verdict per sample of the judged read-back (GL, else the emulation): 0 pass,
  // 1 quality warning, 2 fail.
  std::string envelopeJudged;
  std::vector<std::uint8_t> envelope;
  std::size_t envelopeWarn = 0, envelopeFail = 0;
  nlohmann::json envelopeFailures = nlohmann::json::array();  // the first failing values with intervals
  double envelopeThreshold = 0.0;
  std::string envelopeBasis = "spec";         // emu::CombinationEnvelope::basis
  std::string envelopeSpecStages;             // emu::CombinationEnvelope::specStages
  std::pair<int, int> envelopeUvwBits{7, 4};  // subtexel bits of a pass and of a quality warning
  double envelopeWidest = 0.0;                // the widest pass interval over all samples (its discriminating power)
  std::vector<Finding> departures;
  // Envelope failures and warnings at samples that no departure changes: a finding the model of
  // the driver does not explain.
  std::size_t unexplainedFail = 0, unexplainedWarn = 0;
  // The samples the report magnifies (CaseResult::worstPixels), in data units (codes decoded
  // times the read-back scale, as the reference): exact mismatches (largest code distance) and
  // envelope failures (farthest outside) taken in turn, then quality warnings; when nothing is
  // wrong, the largest distances from the reference.
  std::vector<PixelValues> worst;
  double secondsGl = 0.0, secondsEmulation = 0.0, secondsReference = 0.0;
};

// Builds the sparse grid, textures and frame of `scene`, runs the three paths and the envelope.
// Throws SceneError / io::IoError for a bad scene or data file.
std::shared_ptr<CombinationPlanes> computeCombinationPlanes(CaseContext& ctx, const SparseGridScene& scene);

// The full case: planes (cached by planeKey), shading, oracles, findings, images.
CaseResult judgeCombination(CaseContext& ctx, const std::string& id, const std::string& description,
                            const SparseGridScene& scene);

Case combinationCase(std::string id, std::string description, SparseGridScene scene);

}  // namespace voxref::conf
