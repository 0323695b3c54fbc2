// The study of `voxref bench` (ids study.<system>): every precision variant of every system,
// measured side by side in one run, in one shape. Each system contributes groups; a group varies
// one knob (framebuffer format, sampler path, address encoding, page size, error threshold, exact
// against extracted surface) and states what its error, time and memory figures mean. Per
// variant: the error against the system's reference, the time as the median of repeated runs with
// its spread (min and max), and the memory the variant holds. The study's tables go into
// bench.md and results.json; studyPlots() turns each group into an accuracy-against-time plot.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/bench/bench.h"
#include "conformance/bench/plots.h"

namespace voxref::conf {

// Repeated runs per timed variant: enough for a median and a spread (bench.h measure()).
inline constexpr int kStudyRuns = 5;

struct StudyVariant {
  std::string name;  // "rgba8", "paper / rgba16", "2^12 points"
  // The group's error figure (smaller is better), or NaN when it could not be measured (then
  // `missing` says why and the variant is listed but not plotted).
  double error = std::numeric_limits<double>::quiet_NaN();
  nlohmann::json figures = nlohmann::json::object();  // every error figure measured
  Timing time;                                        // runs == 0: not timed (see `missing`)
  double memoryBytes = std::numeric_limits<double>::quiet_NaN();
  std::string missing;  // why error or time is absent; empty when both were measured
};

struct StudyGroup {
  std::string knob;    // what varies: "framebuffer format"
  std::string error;   // what the error figure is: "RMSE against the double combination technique"
  std::string time;    // what was timed: "GL frame (llvmpipe), read-back included"
  std::string memory;  // what the memory figure counts: "textures + one plane's colour buffer"
  // Plot memory instead of error on the vertical axis: for lossless variants, whose error is 0
  // by construction (checked), the trade-off is size against time.
  bool plotMemory = false;
  std::vector<StudyVariant> variants;
  std::string note;  // how it was measured
};

// The markdown and JSON of one system's study: a table with one row per variant (knob, variant,
// error, median time, spread and runs, memory) and, in data["groups"], every group with its
// variants as numbers (what studyPlots() and results.json read).
BenchTable studyTable(const std::string& id, const std::string& title, const std::vector<StudyGroup>& groups,
                      const std::string& notes);

// One plot per group of a study table (ids "<table id>.<n>"), from table.data alone: error (or
// memory) against median time, each time with its min-max spread as a horizontal bar; variants
// without both figures are named in the plot's note. Tables that are not studies give none.
std::vector<AccuracyPlot> studyPlots(const BenchTable& table);

// "12.3 MB" (MiB), "456 kB" (KiB), "789 B".
std::string bytesText(double bytes);

}  // namespace voxref::conf
