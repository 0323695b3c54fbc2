// `voxref bench`: accuracy-versus-time tables of the systems, measured side by side in one run
// on this machine, written as markdown and JSON. Timings are reported, never asserted.
#pragma once

#include <array>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gpu/context.h"

namespace voxref::conf {

struct BenchOptions {
  std::string filter = "*";
  std::filesystem::path out;
  gpu::Driver driver = gpu::Driver::Llvmpipe;
  bool quick = false;  // small sizes and levels: a smoke run that every test run can afford
  int threads = 0;
  std::filesystem::path volumes;  // the real volumes (../shared/data/volumes); empty: the built-in default
};

// The folder of real volumes the benchmarks read: options.volumes, else the build's default.
std::filesystem::path benchVolumes(const BenchOptions& options);

struct BenchTable {
  std::string id;  // "sparsegrid.table1_time"
  std::string title;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  std::string notes;  // how it was measured, what is estimated
  nlohmann::json data = nlohmann::json::object();
};

std::string markdown(const BenchTable& table);

// A measured duration: the median of `runs` runs (one run when a run takes a second or more).
struct Timing {
  double median = 0.0, min = 0.0, max = 0.0;
  int runs = 0;
  bool estimated = false;  // extrapolated from part of the work
};
nlohmann::json toJson(const Timing& t);
std::string formatSeconds(const Timing& t);
// Median of repeated runs of fn: at least `minRuns` runs; beyond those, more while a run takes
// under a second, up to five within about two seconds. min and max give the spread.
Timing measure(const std::function<void()>& fn, int minRuns = 1);
// Two things compared as a ratio, side by side: `rounds` runs of each (at least one), taking turns
// (a then b in even rounds, b then a in odd ones), so that a drift of the machine's speed during the
// run falls on both alike. Returns their Timings, a's first.
std::array<Timing, 2> measureTakingTurns(const std::function<void()>& a, const std::function<void()>& b, int rounds);
// The Timing of measured runs (seconds each; at least one): their median, min and max.
Timing timingOf(std::vector<double> runs);
// One run of fn.
Timing measureOnce(const std::function<void()>& fn);
// printf-style formatting of one number ("%.2f:1").
std::string formatNumber(const char* format, double v);

// Runs the benchmarks whose id matches the filter (the study, study.h, is study.*), writes
// bench.md, results.json and index.html (bench_html.h) into the output folder and, per study
// group, an accuracy-against-time plot into its plots/ (plots.h), and prints the markdown. Returns the exit status: 0;
// 1 when a plot is due but could not be made (gnuplot missing or failing: the tables are still written and the markdown
// says why). Throws UsageError when nothing matches.
int runBenchmarks(const BenchOptions& options, std::ostream& out);

}  // namespace voxref::conf
