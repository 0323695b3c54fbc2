// The envelope oracle of the time-varying cases (emulation/timevarying_envelope.h) and the samples
// they single out for the report.
//
// Per step it judges the GL read-back (the emulation's when GL did not run) against the pass
// envelope (kEnvelopePass) and, outside it, the quality-warning envelope (kEnvelopeQualityWarning):
// pass / warn / fail per sample. It lists the first failures with the sample, the step, the RGBA8
// value, the channel that misses and the codes the envelope allows in that channel (the nearest
// allowed candidate's interval), flags the pixels of the first step for the error mask (planes
// collapsed), and ranks samples for CaseResult::worstPixels: GL != emulation first, then envelope
// failures, then warnings (round robin, worst first); when nothing is wrong, the largest
// differences from the exact decoder. Values are RGBA8 codes of the channel named in the figures.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/framework/case.h"
#include "conformance/framework/report/case_images.h"
#include "emulation/timevarying_envelope.h"

namespace voxref::conf {

class TimeVaryingEnvelopeOracle {
 public:
  // Throws std::invalid_argument as TimeVaryingEnvelope does.
  TimeVaryingEnvelopeOracle(const ref::TimeVaryingTextures& textures, ref::DecoderVariant decoder,
                            const ref::PlaneFrame& frame, bool composite, const emu::MeasuredArithmetic& measured = {});

  // One step. gl and emulated may be null (not run); nothing is judged when both are. `flags`
  // (width x height), when given, receives this step's flags (call it for the first step only).
  void add(int step, const ref::RgbaStack* gl, const ref::RgbaStack* emulated, const ref::RgbaStack& reference,
           int threads, std::vector<PixelFlag>* flags);

  OracleResult result() const;
  std::vector<PixelValues> worstPixels() const;

 private:
  struct Candidate {
    double score;
    int kind;  // 0 exact mismatch, 1 envelope failure, 2 envelope warning, 3 ideal difference
    PixelValues values;
  };
  void keep(int kind, int step, const std::vector<double>& scores, const ref::RgbaStack* gl,
            const ref::RgbaStack* emulated, const ref::RgbaStack& reference, const std::vector<int>& channel);
  PixelValues valuesAt(std::size_t idx, int channel, const ref::RgbaStack* gl, const ref::RgbaStack* emulated,
                       const ref::RgbaStack& reference) const;

  emu::TimeVaryingEnvelope envelope_;
  const ref::PlaneFrame* frame_;
  bool composite_;
  std::string judged_;  // "gl" or "emulation"; empty until something is judged
  std::size_t samples_ = 0, warnings_ = 0, failures_ = 0;
  int widestCodes_ = 0;
  nlohmann::json widestAt_ = nullptr;
  nlohmann::json failureList_ = nlohmann::json::array();
  std::vector<Candidate> candidates_;
};

}  // namespace voxref::conf
