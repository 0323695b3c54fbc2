#include "conformance/framework/run_summary.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <ostream>

#include "conformance/framework/expectations/outcomes.h"
#include "conformance/framework/report/judgement_counts.h"

namespace voxref::conf {

void printRunSummary(std::ostream& out, const std::vector<CaseResult>& results, int slowest) {
  std::map<Status, int> counts;
  std::map<std::string, int> outcomes;
  bool outcomesDiffer = false;
  for (const CaseResult& r : results) {
    ++counts[r.status];
    ++outcomes[r.outcome];
    const bool differs = !r.outcome.empty() && r.outcome != deqpStatusName(r.status);
    outcomesDiffer = outcomesDiffer || differs;
    if (r.status == Status::Pass && !differs) continue;
    out << "  " << (differs ? r.outcome + " (" + std::string(name(r.status)) + ")" : std::string(name(r.status)))
        << "  " << r.id << ": " << r.message;
    if (!r.reruns.empty()) {
      out << " [reruns:";
      for (Status s : r.reruns) out << " " << name(s);
      out << "]";
    }
    out << "\n";
  }
  out << "summary:";
  for (Status s : {Status::Pass, Status::Warn, Status::Fail, Status::Skip, Status::Crash, Status::Timeout})
    out << " " << counts[s] << " " << name(s);
  out << "\n";
  if (outcomesDiffer) {
    out << "outcomes:";
    for (const auto& [o, n] : outcomes) out << " " << n << " " << o;
    out << "\n";
  }
  out << judgementLines(results);
  std::vector<const CaseResult*> bySeconds;
  for (const CaseResult& r : results) bySeconds.push_back(&r);
  std::stable_sort(bySeconds.begin(), bySeconds.end(),
                   [](const CaseResult* a, const CaseResult* b) { return a->seconds > b->seconds; });
  if (slowest > 0 && !bySeconds.empty()) {
    out << "slowest:";
    for (std::size_t i = 0; i < bySeconds.size() && i < static_cast<std::size_t>(slowest); ++i) {
      char s[32];
      std::snprintf(s, sizeof s, "%.2f s", bySeconds[i]->seconds);
      out << (i ? ", " : " ") << bySeconds[i]->id << " " << s;
    }
    out << "\n";
  }
}

}  // namespace voxref::conf
