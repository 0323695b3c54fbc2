// voxref's own entropy stage for the LEB deltas (issue 18, goal 5: reference/leb/adaptive_delta_coder.h)
// against the paper's lead-1 code and the general-purpose coders, on every volume of the volumes
// folder as stored (`voxref bench --filter leb.coder`): per channel the ratio and the decode speed
// (one thread) of each coder, in one run, and whether the adaptive coder beats xz -9 on the data
// and zstd -19 on the gradients (the goal). Every coded page is decoded and compared with its
// deltas in the run. The adaptive coder is measured on the deltas alone, with the stream's page
// table counted (12 bytes a stored page, 24 a channel, the header with the data), as a version 3
// stream (`voxref encode --coder adaptive`) holds them. Anchor rows give the goal's coder the same
// random access: the raw channel in pieces of 2^16 samples, each compressed on its own.
#pragma once

#include "conformance/bench/bench.h"
#include "conformance/bench/leb_datasets.h"
#include "conformance/bench/study.h"

namespace voxref::conf {

inline constexpr const char* kLebCoderBenchId = "leb.coder";
BenchTable lebCoderBench(const BenchOptions& options);

// The same coders on one data set (data and gradients together) as a study group: compressed
// bytes against the decode time of the whole volume's deltas, one thread.
StudyGroup lebCoderStudyGroup(const BenchOptions& options, const LebDataset& dataset);

}  // namespace voxref::conf
