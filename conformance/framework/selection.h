// Selecting cases by id: shell-style globs, as `voxref list`, `conform` and `bench` take them.
#pragma once

#include <string>
#include <vector>

#include "conformance/framework/case.h"

namespace voxref::conf {

// The cases whose id matches the shell-style glob (fnmatch: '*', '?', '[...]'; '.' is not
// special), or any of several globs separated by commas (ids hold no commas); in the given order.
std::vector<Case> selectCases(const std::vector<Case>& cases, const std::string& glob);

// True when `id` matches `glob` (or one of its comma-separated globs).
bool globMatch(const std::string& glob, const std::string& id);

}  // namespace voxref::conf
