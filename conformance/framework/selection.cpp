#include "conformance/framework/selection.h"

#include <fnmatch.h>

namespace voxref::conf {

bool globMatch(const std::string& glob, const std::string& id) {
  std::size_t from = 0;
  for (;;) {
    const std::size_t comma = glob.find(',', from);
    const std::string one = glob.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
    if (!one.empty() && fnmatch(one.c_str(), id.c_str(), 0) == 0) return true;
    if (comma == std::string::npos) return false;
    from = comma + 1;
  }
}

std::vector<Case> selectCases(const std::vector<Case>& cases, const std::string& glob) {
  std::vector<Case> out;
  for (const Case& c : cases)
    if (globMatch(glob, c.id)) out.push_back(c);
  return out;
}

}  // namespace voxref::conf
