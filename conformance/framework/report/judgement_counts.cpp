#include "conformance/framework/report/judgement_counts.h"

#include <algorithm>

namespace voxref::conf {

std::vector<std::pair<std::string, SystemJudgement>> judgementCounts(const std::vector<CaseResult>& results) {
  std::vector<std::pair<std::string, SystemJudgement>> out;
  for (const CaseResult& r : results) {
    auto it = std::find_if(out.begin(), out.end(), [&](const auto& p) { return p.first == r.system; });
    if (it == out.end()) it = out.insert(out.end(), {r.system, SystemJudgement{}});
    ++it->second.judgedBy[r.judgedBy];
    ++it->second.outcomes[r.status];
    ++it->second.cases;
    it->second.probedModelFailures += r.probedModelFailed;
  }
  return out;
}

nlohmann::json judgementJson(const std::vector<CaseResult>& results) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [system, s] : judgementCounts(results)) {
    nlohmann::json judged = nlohmann::json::object(), outcomes = nlohmann::json::object();
    for (const Judge k : kJudges) judged[std::string(name(k))] = s.judgedBy.count(k) ? s.judgedBy.at(k) : 0;
    for (const Status st : {Status::Pass, Status::Warn, Status::Fail, Status::Skip, Status::Crash, Status::Timeout})
      outcomes[std::string(name(st))] = s.outcomes.count(st) ? s.outcomes.at(st) : 0;
    j[system] = {{"judged_by", judged},
                 {"outcomes", outcomes},
                 {"cases", s.cases},
                 {"probed_model_failures", s.probedModelFailures}};
  }
  return j;
}

std::string judgementLines(const std::vector<CaseResult>& results) {
  std::string out;
  for (const auto& [system, s] : judgementCounts(results)) {
    std::string judged;
    for (const Judge k : kJudges)
      if (k != Judge::None && s.judgedBy.count(k))
        judged += (judged.empty() ? "" : ", ") + std::to_string(s.judgedBy.at(k)) + " " + std::string(name(k));
    const int none = s.judgedBy.count(Judge::None) ? s.judgedBy.at(Judge::None) : 0;
    out +=
        "  " + system + ": " + std::to_string(s.cases) + " case(s); judged on GL by " +
        (judged.empty() ? "nothing" : judged) + "; not judged " + std::to_string(none) +
        (s.probedModelFailures ? "; " + std::to_string(s.probedModelFailures) +
                                     " exact failure(s) against the probed profile: the probed model does not hold here"
                               : std::string()) +
        "\n";
  }
  return out;
}

}  // namespace voxref::conf
