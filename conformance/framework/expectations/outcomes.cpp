#include "conformance/framework/expectations/outcomes.h"

#include <algorithm>

namespace voxref::conf {

std::string deqpStatusName(Status s) {
  std::string n(name(s));
  n[0] = static_cast<char>(n[0] - 'a' + 'A');
  return n;
}

std::string outcomeName(Outcome o, Status status) {
  switch (o) {
    case Outcome::Pass:
      return "Pass";
    case Outcome::Warn:
      return "Warn";
    case Outcome::Skip:
      return "Skip";
    case Outcome::Fail:
      return "Fail";
    case Outcome::Crash:
      return "Crash";
    case Outcome::Timeout:
      return "Timeout";
    case Outcome::ExpectedFail:
      return "ExpectedFail";
    case Outcome::UnexpectedImprovement:
      return "UnexpectedImprovement(" + deqpStatusName(status) + ")";
    case Outcome::Flake:
      return "Flake";
    case Outcome::KnownFlake:
      return "KnownFlake";
    case Outcome::Missing:
      return "Missing";
  }
  return "?";
}

std::optional<Outcome> parseOutcome(const std::string& text) {
  if (text.rfind("UnexpectedImprovement(", 0) == 0) return Outcome::UnexpectedImprovement;
  for (Outcome o : {Outcome::Pass, Outcome::Warn, Outcome::Skip, Outcome::Fail, Outcome::Crash, Outcome::Timeout,
                    Outcome::ExpectedFail, Outcome::Flake, Outcome::KnownFlake, Outcome::Missing})
    if (outcomeName(o, Status::Pass) == text) return o;
  return std::nullopt;
}

bool failsJob(Outcome o) {
  return o == Outcome::Fail || o == Outcome::Crash || o == Outcome::Timeout || o == Outcome::UnexpectedImprovement ||
         o == Outcome::Missing;
}

bool isFailure(Status s) { return s == Status::Fail || s == Status::Crash || s == Status::Timeout; }

namespace {

Outcome plain(Status s) {
  switch (s) {
    case Status::Pass:
      return Outcome::Pass;
    case Status::Warn:
      return Outcome::Warn;
    case Status::Skip:
      return Outcome::Skip;
    case Status::Fail:
      return Outcome::Fail;
    case Status::Crash:
      return Outcome::Crash;
    case Status::Timeout:
      return Outcome::Timeout;
  }
  return Outcome::Fail;
}

// Better than the expected failing status: a pass, or a warning where a failure was expected.
// A skip is neither better nor worse (nothing judged it): it stays a skip.
bool improves(Status actual, Status expected) {
  if (actual == Status::Pass) return true;
  return actual == Status::Warn && isFailure(expected);
}

}  // namespace

bool wantsRerun(const std::string& id, const CaseResult& result, const Expectations& expectations) {
  if (!isFailure(result.status)) return false;
  const auto it = expectations.fails.find(id);
  if (it != expectations.fails.end() && it->second.status == result.status) return false;
  return firstMatch(expectations.flakes, id) == nullptr;
}

Outcome classify(const std::string& id, const CaseResult* result, const std::vector<Status>& rerunStatuses,
                 const Expectations& expectations) {
  if (!result) return Outcome::Missing;
  const Status s = result->status;
  const auto it = expectations.fails.find(id);
  if (it != expectations.fails.end()) {
    if (s == it->second.status) return Outcome::ExpectedFail;
    if (improves(s, it->second.status)) return Outcome::UnexpectedImprovement;
  }
  if (!isFailure(s)) return plain(s);
  if (firstMatch(expectations.flakes, id)) return Outcome::KnownFlake;
  const bool passedOnRerun = std::any_of(rerunStatuses.begin(), rerunStatuses.end(),
                                         [](Status r) { return r == Status::Pass || r == Status::Warn; });
  return passedOnRerun ? Outcome::Flake : plain(s);
}

}  // namespace voxref::conf
