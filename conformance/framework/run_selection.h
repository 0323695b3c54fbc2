// The cases a `voxref conform` run executes, from its options, in the order deqp-runner applies
// them (docs/ci.md, "Which cases a shard runs"): the catalogue, filtered by --filter and by the
// case lists; the skips file's matches removed; every Nth case kept (--fraction); then the shard.
// Every machine of a fleet computes the same from the same options and catalogue.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "conformance/framework/case.h"
#include "conformance/framework/expectations/expectation_files.h"
#include "conformance/framework/shard.h"

namespace voxref::conf {

struct SelectionRequest {
  std::string filter = "*";
  std::vector<ListedCase> caseList;  // empty: no case list
  const std::vector<Pattern>* skips = nullptr;
  std::string idPrefix;  // skips patterns see the id with it
  int fraction = 1;      // keep every Nth case
  std::optional<Shard> shard;
};

struct Selection {
  std::vector<Case> cases;   // what runs
  std::size_t matched = 0;   // after --filter and the case lists
  std::size_t skipped = 0;   // removed by the skips file
  std::size_t selected = 0;  // after the skips and the fraction: what the shards split
};

// Throws UsageError: a case list names a case the catalogue does not hold (file:line), or nothing
// matches the filter and the lists.
Selection selectRun(const std::vector<Case>& catalogue, const SelectionRequest& request);

}  // namespace voxref::conf
