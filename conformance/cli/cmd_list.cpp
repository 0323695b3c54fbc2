#include <iostream>

#include "conformance/framework/selection.h"
#include "conformance/modules/catalog.h"
#include "conformance/cli/case_selection.h"
#include "conformance/cli/commands.h"
#include "conformance/framework/runner.h"

namespace voxref::cli {

int runList(const ListOptions& o) {
  auto cases = conf::selectCases(catalogue(o.runnerControls), o.filter);
  if (cases.empty()) throw conf::UsageError("no case matches '" + o.filter + "'");
  if (const auto shard = shardOption(o.shard)) cases = conf::shardOf(cases, *shard);
  std::size_t width = 0;
  for (const auto& c : cases) width = std::max(width, c.id.size());
  for (const auto& c : cases) std::cout << c.id << std::string(width + 2 - c.id.size(), ' ') << c.description << "\n";
  return 0;
}

}  // namespace voxref::cli
