// Cases that misbehave on purpose, to prove that the runner survives what drivers do: a crash
// inside the GL driver, a segmentation fault, an abort, an exit without a result, a hang and
// an exception. They are never in the default catalogue; `voxref conform --runner-controls`
// (and `voxref list --runner-controls`) add them. Each writes a line to stderr before it
// misbehaves, so a report can show that the case's stderr was kept.
#pragma once

#include <vector>

#include "conformance/framework/case.h"

namespace voxref::conf {

// Ids "runner.control.*"; the expected status of each is in its description.
std::vector<Case> runnerControlCases();

}  // namespace voxref::conf
