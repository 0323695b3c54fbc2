// The catalogue of built-in cases: every system's cases (modules/<system>/<system>_catalog.h), in
// the papers' order. Selecting from it: framework/selection.h.
#pragma once

#include <vector>

#include "conformance/framework/case.h"

namespace voxref::conf {

// Every built-in case, in catalogue order (systems in paper order).
std::vector<Case> allCases();

}  // namespace voxref::conf
