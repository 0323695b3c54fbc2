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

std::string_view name(Judge j) {
  switch (j) {
    case Judge::None:
      return "none";
    case Judge::Exact:
      return "exact";
    case Judge::Envelope:
      return "envelope";
    case Judge::Fetch:
      return "fetch";
    case Judge::IsoGeometry:
      return "iso_geometry";
    case Judge::Prediction:
      return "prediction";
    case Judge::GlBehaviour:
      return "gl_behaviour";
  }
  return "?";
}

std::optional<Judge> parseJudge(std::string_view s) {
  for (Judge j : kJudges)
    if (name(j) == s) return j;
  return std::nullopt;
}

namespace {

std::string firstLine(const std::string& s) {
  return s.empty() ? std::string("(no summary)") : s.substr(0, s.find('\n'));
}

}  // namespace

void concludeFromOracles(CaseResult& result) {
  result.status = statusFromOracles(result.oracles);
  result.message.clear();
  for (const Verdict wanted : {Verdict::Fail, Verdict::Warn})
    for (const OracleResult& o : result.oracles)
      if (result.message.empty() && o.verdict == wanted) result.message = o.oracle + ": " + firstLine(o.summary);
  result.judgedBy = Judge::None;
  for (const Judge j : kJudges)
    for (const OracleResult& o : result.oracles)
      if (result.judgedBy == Judge::None && j != Judge::None && o.judges == j &&
          (o.verdict == Verdict::Pass || o.verdict == Verdict::Warn || o.verdict == Verdict::Fail))
        result.judgedBy = j;
  if (result.judgedBy != Judge::None || result.status == Status::Fail) return;
  // Nothing judged GL's output: never a pass. The reason: why each oracle that could have judged did not.
  std::string why;
  for (const OracleResult& o : result.oracles)
    if (o.verdict != Verdict::Info) why += (why.empty() ? "" : "; ") + o.oracle + ": " + firstLine(o.summary);
  result.status = Status::Skip;
  result.message =
      "not judged on this driver: " + (why.empty() ? std::string("no oracle of this case judges the GL output") : why);
}

void markProbedModelFailure(CaseResult& result) {
  for (const OracleResult& o : result.oracles)
    if (o.judges == Judge::Exact && o.verdict == Verdict::Fail && !result.probedModelFailed) {
      result.probedModelFailed = true;
      result.message = "the probed model does not hold here: " + result.message;
    }
}

}  // namespace voxref::conf
