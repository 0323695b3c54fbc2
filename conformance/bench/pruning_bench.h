// Effect pruning measured (issue 7; docs/design.md, "Scenes and effects"): built-in scenes emulated
// with only the stages they call for and with every skipped stage forced on (forceAllEffects),
// side by side in one run: the time of each, the ratio, and that the bits are identical.
// `voxref bench --filter 'pruning*'`.
#pragma once

#include <string>
#include <vector>

#include "conformance/bench/bench.h"
#include "emulation/profile.h"

namespace voxref::conf {

std::vector<std::string> pruningBenchIds();
std::vector<BenchTable> pruningBench(const BenchOptions& options, const emu::PrecisionProfile* profile);

}  // namespace voxref::conf
