// A case's outcome against the run's expectation files, in deqp-runner's vocabulary (docs/ci.md):
// what results.csv and failures.csv hold and what decides the exit status of a CI job.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "conformance/framework/case.h"
#include "conformance/framework/expectations/expectation_files.h"

namespace voxref::conf {

enum class Outcome {
  Pass,
  Warn,  // a quality warning, not expected: reported, not a failure (as before)
  Skip,  // the case skipped (unsupported, or nothing judged it)
  Fail,  // failed, not expected, and failed again on every rerun
  Crash,
  Timeout,
  ExpectedFail,           // the status the fails file names
  UnexpectedImprovement,  // the fails file names a status, the case did better: fails the job
  Flake,                  // failed unexpectedly, then passed on a rerun: reported, not a failure
  KnownFlake,             // failed, and matches the flakes file: not a failure
  Missing,                // selected, and no result: fails the job
};

// "Pass", "ExpectedFail", "UnexpectedImprovement(Pass)" ... as deqp-runner prints them; `status` is
// the case's status (its improvement, for UnexpectedImprovement).
std::string outcomeName(Outcome o, Status status);

// A status as deqp-runner spells it, capitalised: "Pass", "Fail", "Crash" ... (the fails file's and
// failures.csv's spelling; name(Status) is results.json's lower-case one).
std::string deqpStatusName(Status s);

// The outcome an outcomeName() names (nullopt for another text).
std::optional<Outcome> parseOutcome(const std::string& text);

// Whether the outcome fails the job (exit status 1): Fail, Crash, Timeout, UnexpectedImprovement
// and Missing.
bool failsJob(Outcome o);

// A status that counts as failed (Fail, Crash, Timeout): what gets rerun and what a fails file
// expects (with Warn).
bool isFailure(Status s);

// The outcome of one case: `result` is null where it produced none (Missing); `rerunStatuses` are
// the statuses of its reruns, in order (empty when it was not rerun). Pure: the rules of
// docs/ci.md, "Outcomes".
Outcome classify(const std::string& id, const CaseResult* result, const std::vector<Status>& rerunStatuses,
                 const Expectations& expectations);

// Whether a case with this first result is rerun to tell a flake: it failed (isFailure), the fails
// file does not expect that status, and no flakes pattern matches it.
// `id` is the case's id as the expectation files name it (with the run's prefix).
bool wantsRerun(const std::string& id, const CaseResult& result, const Expectations& expectations);

}  // namespace voxref::conf
