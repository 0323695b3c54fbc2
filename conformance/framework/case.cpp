#include "conformance/framework/case.h"

namespace voxref::conf {

std::string_view name(Status s) {
  switch (s) {
    case Status::Pass:
      return "pass";
    case Status::Warn:
      return "warn";
    case Status::Fail:
      return "fail";
    case Status::Skip:
      return "skip";
    case Status::Crash:
      return "crash";
    case Status::Timeout:
      return "timeout";
  }
  return "?";
}

std::string_view name(Verdict v) {
  switch (v) {
    case Verdict::Pass:
      return "pass";
    case Verdict::Warn:
      return "warn";
    case Verdict::Fail:
      return "fail";
    case Verdict::NotRun:
      return "not_run";
    case Verdict::Info:
      return "info";
  }
  return "?";
}

std::optional<Status> parseStatus(std::string_view s) {
  for (Status v : {Status::Pass, Status::Warn, Status::Fail, Status::Skip, Status::Crash, Status::Timeout})
    if (name(v) == s) return v;
  return std::nullopt;
}

std::optional<Verdict> parseVerdict(std::string_view s) {
  for (Verdict v : {Verdict::Pass, Verdict::Warn, Verdict::Fail, Verdict::NotRun, Verdict::Info})
    if (name(v) == s) return v;
  return std::nullopt;
}

Status statusFromOracles(const std::vector<OracleResult>& oracles) {
  Status s = Status::Pass;
  for (const OracleResult& o : oracles) {
    if (o.verdict == Verdict::Fail) return Status::Fail;
    if (o.verdict == Verdict::Warn) s = Status::Warn;
  }
  return s;
}

void concludeFromOracles(CaseResult& result) {
  result.status = statusFromOracles(result.oracles);
  result.message.clear();
  for (const Verdict wanted : {Verdict::Fail, Verdict::Warn})
    for (const OracleResult& o : result.oracles)
      if (result.message.empty() && o.verdict == wanted) {
        const std::string summary = o.summary.empty() ? "(no summary)" : o.summary;
        result.message = o.oracle + ": " + summary.substr(0, summary.find('\n'));
      }
}

}  // namespace voxref::conf
