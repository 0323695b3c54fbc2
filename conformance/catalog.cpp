#include "conformance/catalog.h"

#include <fnmatch.h>

#include "conformance/iso/iso_catalog.h"
#include "conformance/sparsegrid/sparsegrid_catalog.h"
#include "conformance/timevarying/timevarying_catalog.h"

namespace voxref::conf {

std::vector<Case> allCases() {
  std::vector<Case> cases = sparseGridCases();
  for (Case& c : timeVaryingCases()) cases.push_back(std::move(c));
  for (Case& c : isoCases()) cases.push_back(std::move(c));
  return cases;
}

bool globMatch(const std::string& glob, const std::string& id) { return fnmatch(glob.c_str(), id.c_str(), 0) == 0; }

std::vector<Case> selectCases(const std::vector<Case>& cases, const std::string& glob) {
  std::vector<Case> out;
  for (const Case& c : cases)
    if (globMatch(glob, c.id)) out.push_back(c);
  return out;
}

}  // namespace voxref::conf
