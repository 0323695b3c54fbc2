#include "conformance/framework/run_selection.h"

#include <set>

#include "conformance/framework/exit_status.h"
#include "conformance/framework/selection.h"

namespace voxref::conf {

Selection selectRun(const std::vector<Case>& catalogue, const SelectionRequest& request) {
  std::vector<Case> cases = selectCases(catalogue, request.filter);
  if (!request.caseList.empty()) {
    std::set<std::string> known, listed;
    for (const Case& c : catalogue) known.insert(c.id);
    for (const ListedCase& l : request.caseList) {
      if (!known.count(l.id))
        throw UsageError(l.from.file + ":" + std::to_string(l.from.line) + ": no case '" + l.id +
                         "' in the catalogue (voxref list shows them)");
      listed.insert(l.id);
    }
    std::vector<Case> inList;
    for (Case& c : cases)
      if (listed.count(c.id)) inList.push_back(std::move(c));
    cases = std::move(inList);
  }
  if (cases.empty())
    throw UsageError("no case matches '" + request.filter + "'" +
                     (request.caseList.empty() ? "" : " and the case list") + " (voxref list shows them)");
  Selection s;
  s.matched = cases.size();
  if (request.skips && !request.skips->empty()) {
    std::vector<Case> kept;
    for (Case& c : cases)
      if (!firstMatch(*request.skips, request.idPrefix + c.id)) kept.push_back(std::move(c));
    s.skipped = cases.size() - kept.size();
    cases = std::move(kept);
  }
  cases = fractionOf(cases, request.fraction);
  s.selected = cases.size();
  s.cases = request.shard ? shardOf(cases, *request.shard) : std::move(cases);
  return s;
}

}  // namespace voxref::conf
