#include "conformance/modules/catalog.h"

#include "conformance/modules/iso/iso_catalog.h"
#include "conformance/modules/sparsegrid/sparsegrid_catalog.h"
#include "conformance/modules/timevarying/timevarying_catalog.h"

namespace voxref::conf {

std::vector<Case> allCases() {
  std::vector<Case> cases = sparseGridCases();
  for (Case& c : timeVaryingCases()) cases.push_back(std::move(c));
  for (Case& c : isoCases()) cases.push_back(std::move(c));
  return cases;
}

}  // namespace voxref::conf
