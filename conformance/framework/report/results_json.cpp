#include "conformance/framework/report/results_json.h"

#include "conformance/framework/report/judgement_counts.h"

#include <cmath>
#include <map>

namespace voxref::conf {

nlohmann::json caseJson(const CaseResult& r) {
  nlohmann::json oracles = nlohmann::json::object();
  for (const OracleResult& o : r.oracles)
    oracles[o.oracle] = {
        {"verdict", name(o.verdict)}, {"summary", o.summary}, {"figures", o.figures}, {"judges", name(o.judges)}};
  nlohmann::json findings = nlohmann::json::array();
  for (const Finding& f : r.findings)
    findings.push_back({{"id", f.id}, {"description", f.description}, {"figures", f.figures}});
  nlohmann::json images = nlohmann::json::object();
  if (!r.images.rendered.empty()) images["rendered"] = r.images.rendered;
  if (!r.images.emulated.empty()) images["emulated"] = r.images.emulated;
  if (!r.images.reference.empty()) images["reference"] = r.images.reference;
  if (!r.images.errorMask.empty()) images["error_mask"] = r.images.errorMask;
  nlohmann::json worst = nlohmann::json::array();
  for (const PixelValues& p : r.worstPixels) {
    auto num = [](double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); };
    nlohmann::json w = {{"x", p.x},
                        {"y", p.y},
                        {"k", p.k},
                        {"oracle", p.oracle},
                        {"gl", num(p.gl)},
                        {"emulated", num(p.emulated)},
                        {"reference", num(p.reference)}};
    if (p.allowed) w["allowed"] = {p.allowed->first, p.allowed->second};
    worst.push_back(w);
  }
  nlohmann::json reruns = nlohmann::json::array();
  for (Status s : r.reruns) reruns.push_back(name(s));
  return {{"id", r.id},
          {"system", r.system},
          {"description", r.description},
          {"status", name(r.status)},
          {"message", r.message},
          {"judged_by", name(r.judgedBy)},
          {"probed_model_failed", r.probedModelFailed},
          {"stderr", r.stderrText},
          {"oracles", oracles},
          {"effects", r.effects},
          {"findings", findings},
          {"figures", r.figures},
          {"seconds_gl", r.secondsGl},
          {"seconds_emulation", r.secondsEmulation},
          {"seconds_reference", r.secondsReference},
          {"timings", r.timings},
          {"seconds", r.seconds},
          {"reruns", reruns},
          {"outcome", r.outcome},
          {"images", images},
          {"worst_pixels", worst}};
}

nlohmann::json resultsJson(const RunInfo& run, const std::vector<CaseResult>& results) {
  std::map<std::string, int> counts{{"pass", 0}, {"warn", 0}, {"fail", 0}, {"skip", 0}, {"crash", 0}, {"timeout", 0}};
  nlohmann::json cases = nlohmann::json::array();
  for (const CaseResult& r : results) {
    ++counts[std::string(name(r.status))];
    cases.push_back(caseJson(r));
  }
  return {{"format", "voxref-results"},
          {"format_version", 1},
          {"command", run.command},
          {"started", run.started},
          {"finished", run.finished},
          {"complete", run.complete},
          {"running", run.running},
          {"interrupted_by", run.interruptedBy.empty() ? nlohmann::json(nullptr) : nlohmann::json(run.interruptedBy)},
          {"not_run", run.notRun},
          {"execution", run.execution},
          {"baseline", run.baseline},
          {"driver", run.driver},
          {"summary", counts},
          {"judgement", judgementJson(results)},
          {"cases", cases}};
}

std::string resultsText(const RunInfo& run, const std::vector<CaseResult>& results) {
  return resultsJson(run, results).dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

}  // namespace voxref::conf
