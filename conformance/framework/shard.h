// Splitting a selection of cases between machines (`voxref conform --shard I/N`).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "conformance/framework/case.h"

namespace voxref::conf {

struct Shard {
  int index = 1;  // 1-based
  int count = 1;
};

// "I/N" with 1 <= I <= N; throws std::invalid_argument naming what is wrong otherwise.
Shard parseShard(const std::string& text);

// The cases of shard I of N: those at positions p (0-based, in the order of `selection`, which is
// catalogue order) with p mod N == I - 1. Deterministic for a given catalogue and filter; the N
// shards are disjoint, their union is the selection, and their sizes differ by at most one.
std::vector<Case> shardOf(const std::vector<Case>& selection, const Shard& shard);

// Every Nth case of `selection` (positions 0, N, 2N ...), as deqp-runner's --fraction N; N >= 1.
std::vector<Case> fractionOf(const std::vector<Case>& selection, int n);

// The shard GitLab CI assigns a job of `parallel: N`: CI_NODE_INDEX (1-based) of CI_NODE_TOTAL,
// given their values (nullptr: unset). nullopt when neither is set; std::invalid_argument naming
// the variable when one is set without the other or either is not a whole number in range.
std::optional<Shard> shardFromCiVariables(const char* nodeIndex, const char* nodeTotal);

}  // namespace voxref::conf
