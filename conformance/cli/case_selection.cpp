#include "conformance/cli/case_selection.h"

#include <cstdlib>
#include <stdexcept>

#include "conformance/framework/controls/runner_controls.h"
#include "conformance/framework/exit_status.h"
#include "conformance/modules/catalog.h"

namespace voxref::cli {

std::vector<conf::Case> catalogue(bool runnerControls) {
  if (!runnerControls) return conf::allCases();
  // First, so that every selected built-in case runs after them: proof that the run goes on.
  std::vector<conf::Case> cases = conf::runnerControlCases();
  for (conf::Case& c : conf::allCases()) cases.push_back(std::move(c));
  return cases;
}

std::optional<conf::Shard> shardOption(const std::string& text) {
  if (text.empty()) return std::nullopt;
  try {
    return conf::parseShard(text);
  } catch (const std::invalid_argument& e) {
    throw conf::UsageError(e.what());
  }
}

std::optional<conf::Shard> shardOptionOrCi(const std::string& text, std::string& from) {
  from = "--shard";
  if (!text.empty()) return shardOption(text);
  from = "CI_NODE_INDEX/CI_NODE_TOTAL";
  try {
    return conf::shardFromCiVariables(std::getenv("CI_NODE_INDEX"), std::getenv("CI_NODE_TOTAL"));
  } catch (const std::invalid_argument& e) {
    throw conf::UsageError(e.what());
  }
}

}  // namespace voxref::cli
