// Conformance of the time-varying decoders (Binotto et al. 2003): one scene through the GL path,
// its emulation and the exact decoder.
//
//   exact   GL read-back == emulation, every channel of every sample of every time step (decode
//           planes) or every pixel of the composited image, bit for bit;
//   fetch   the texels the emulation fetched against the exact decoder's integer addresses
//           (fetch_classification.h): wrong voxels and wrong blocks, and where. For the corrected
//           decoders (texel_centre, texel_fetch) every fetch must be right; for the paper's
//           addressing the counts are the finding;
//   ideal   the GL colours against the exact decoder (decode planes), or the composited image
//           against the exact colours composited in real arithmetic (max channel difference in
//           LSB, RMSE).
//   envelope the GL read-back (the emulation's without GL) against what any conforming implementation
//           may produce (emulation/timevarying_envelope.h, timevarying_envelope_conf.h): pass, quality
//           warning or fail per sample, the allowed codes listed for every failure.
#pragma once

#include <string>

#include "conformance/framework/case.h"
#include "conformance/framework/case_context.h"
#include "conformance/modules/timevarying/timevarying_scene.h"

namespace voxref::conf {

struct TimeVaryingExpectation {
  bool everyFetchRight = false;  // the fetch oracle fails on any wrong voxel, block or colour
  bool trapReproduced = false;   // the fetch oracle fails unless some colours come out wrong (a paper trap)
};

CaseResult judgeTimeVarying(CaseContext& ctx, const std::string& id, const std::string& description,
                            const TimeVaryingScene& scene, const TimeVaryingExpectation& expectation);

Case timeVaryingCase(std::string id, std::string description, TimeVaryingScene scene,
                     TimeVaryingExpectation expectation);

}  // namespace voxref::conf
