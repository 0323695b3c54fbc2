// The catalogue of built-in cases, and selecting from it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "conformance/case.h"

namespace voxref::conf {

// Every built-in case, in catalogue order (systems in paper order).
std::vector<Case> allCases();

// The cases whose id matches the shell-style glob (fnmatch: '*', '?', '[...]'; '.' is not
// special), or any of several globs separated by commas (ids hold no commas); catalogue order.
std::vector<Case> selectCases(const std::vector<Case>& cases, const std::string& glob);

// True when `id` matches `glob` (or one of its comma-separated globs).
bool globMatch(const std::string& glob, const std::string& id);

}  // namespace voxref::conf
