// What `voxref list` and `voxref conform` choose cases from, and their --shard option.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "conformance/framework/case.h"
#include "conformance/framework/shard.h"

namespace voxref::cli {

// The built-in catalogue, after the runner's control cases (runner_controls.h) when asked for.
std::vector<conf::Case> catalogue(bool runnerControls);

// nullopt for an empty option; conf::UsageError for a malformed one.
std::optional<conf::Shard> shardOption(const std::string& text);

// --shard when given, else the shard GitLab's CI_NODE_INDEX and CI_NODE_TOTAL name (conf::
// shardFromCiVariables), else nullopt; `from` says which. conf::UsageError for a malformed one.
std::optional<conf::Shard> shardOptionOrCi(const std::string& text, std::string& from);

}  // namespace voxref::cli
