// The built-in time-varying cases (Binotto et al. 2003): every decoder on every kind of sample
// point, decode-only and composited, and the hard cases. Built-in data is synthetic.
#pragma once

#include <vector>

#include "conformance/framework/case.h"

namespace voxref::conf {

std::vector<Case> timeVaryingCases();

}  // namespace voxref::conf
