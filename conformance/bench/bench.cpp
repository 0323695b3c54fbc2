#include "conformance/bench/bench.h"
#include "conformance/framework/selection.h"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <ostream>
#include <sstream>

#include "conformance/bench/bench_html.h"
#include "conformance/bench/iso_bench.h"
#include "conformance/bench/leb_bench.h"
#include "conformance/bench/plots.h"
#include "conformance/bench/pruning_bench.h"
#include "conformance/bench/sparsegrid_bench.h"
#include "conformance/bench/study.h"
#include "conformance/bench/timevarying_bench.h"
#include "conformance/framework/driver_info.h"
#include "conformance/framework/exit_status.h"
#include "conformance/io/atomic_file.h"
#include "conformance/modules/catalog.h"
#include "reference/common/parallel.h"

namespace voxref::conf {

std::string markdown(const BenchTable& t) {
  std::ostringstream m;
  m << "### " << t.title << "\n\n|";
  for (const auto& c : t.columns) m << " " << c << " |";
  m << "\n|";
  for (std::size_t i = 0; i < t.columns.size(); ++i) m << (i ? " ---: |" : " --- |");
  m << "\n";
  for (const auto& row : t.rows) {
    m << "|";
    for (const auto& cell : row) m << " " << cell << " |";
    m << "\n";
  }
  if (!t.notes.empty()) m << "\n" << t.notes << "\n";
  return m.str() + "\n";
}

nlohmann::json toJson(const Timing& t) {
  return {{"median_s", t.median}, {"min_s", t.min}, {"max_s", t.max}, {"runs", t.runs}, {"estimated", t.estimated}};
}

std::string formatSeconds(const Timing& t) {
  char buf[64];
  if (t.median >= 100)
    std::snprintf(buf, sizeof buf, "%.0f s", t.median);
  else if (t.median >= 1)
    std::snprintf(buf, sizeof buf, "%.2f s", t.median);
  else if (t.median >= 1e-3)
    std::snprintf(buf, sizeof buf, "%.1f ms", t.median * 1e3);
  else
    std::snprintf(buf, sizeof buf, "%.3g us", t.median * 1e6);
  return std::string(buf) + (t.estimated ? "*" : "");
}

std::filesystem::path benchVolumes(const BenchOptions& o) {
  return o.volumes.empty() ? std::filesystem::path(VOXREF_DEFAULT_SHARED_VOLUMES) : o.volumes;
}

Timing measure(const std::function<void()>& fn, int minRuns) {
  using Clock = std::chrono::steady_clock;
  std::vector<double> runs;
  const auto start = Clock::now();
  do {
    const auto t0 = Clock::now();
    fn();
    runs.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  } while (
      static_cast<int>(runs.size()) < minRuns ||
      (runs.front() < 1.0 && runs.size() < 5 && std::chrono::duration<double>(Clock::now() - start).count() < 2.0));
  return timingOf(std::move(runs));
}

std::array<Timing, 2> measureTakingTurns(const std::function<void()>& a, const std::function<void()>& b, int rounds) {
  std::array<std::vector<double>, 2> runs;
  for (int r = 0; r < std::max(1, rounds); ++r)
    for (const int which : {r % 2, 1 - r % 2})
      runs[static_cast<std::size_t>(which)].push_back(measureOnce(which == 0 ? a : b).median);
  return {timingOf(std::move(runs[0])), timingOf(std::move(runs[1]))};
}

Timing timingOf(std::vector<double> runs) {
  std::sort(runs.begin(), runs.end());
  return {runs[runs.size() / 2], runs.front(), runs.back(), static_cast<int>(runs.size()), false};
}

Timing measureOnce(const std::function<void()>& fn) {
  const auto t0 = std::chrono::steady_clock::now();
  fn();
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {s, s, s, 1, false};
}

std::string formatNumber(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

int runBenchmarks(const BenchOptions& options, std::ostream& out) {
  std::vector<std::string> ids = sparseGridBenchIds();
  for (const auto& id : timeVaryingBenchIds()) ids.push_back(id);
  for (const auto& id : lebBenchIds()) ids.push_back(id);
  for (const auto& id : isoBenchIds()) ids.push_back(id);
  for (const auto& id : pruningBenchIds()) ids.push_back(id);
  bool any = false;
  for (const auto& id : ids) any |= globMatch(options.filter, id);
  if (!any) {
    std::string known;
    for (const auto& id : ids) known += (known.empty() ? "" : ", ") + id;
    throw UsageError("no benchmark matches '" + options.filter + "' (known: " + known + ")");
  }
  io::ensureDirectory(options.out);
  if (findOnPath("gnuplot").empty())
    std::cerr << "voxref bench: warning: gnuplot is not on PATH: no accuracy plot can be made (the tables are still "
                 "written; exit status 1 if a plot is due)\n";
  std::unique_ptr<gpu::Context> gl = gpu::createContext(options.driver);
  std::string how;
  const emu::PrecisionProfile* profile = chooseProfile("auto", gl->info(), how);

  std::vector<BenchTable> tables = sparseGridBench(options, *gl, profile);
  for (BenchTable& t : timeVaryingBench(options, *gl, profile)) tables.push_back(std::move(t));
  for (BenchTable& t : lebBench(options)) tables.push_back(std::move(t));
  for (BenchTable& t : isoBench(options, *gl)) tables.push_back(std::move(t));
  for (BenchTable& t : pruningBench(options, profile)) tables.push_back(std::move(t));
  // The study first (study.h), then the papers' tables and the other measurements.
  std::stable_partition(tables.begin(), tables.end(), [](const BenchTable& t) { return t.id.rfind("study.", 0) == 0; });
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  const double peakBytes = static_cast<double>(usage.ru_maxrss) * 1024.0;
  const std::string header = "Driver: " + gl->info().renderer + " (" + gl->info().version + "), profile " +
                             (profile ? std::string(profile->name) : "none") +
                             ". CPU threads: " + std::to_string(ref::workerCount(options.threads)) +
                             ". Peak resident memory of the whole run: " + bytesText(peakBytes) + "." +
                             (options.quick ? " Quick mode (smoke run: small sizes)." : "");
  std::string md = "# voxref bench\n\n" + header + "\n\n";
  nlohmann::json json = {{"driver", driverJson(gl->info(), profile, how)},
                         {"quick", options.quick},
                         {"threads", ref::workerCount(options.threads)},
                         {"peak_resident_bytes", peakBytes},
                         {"tables", nlohmann::json::array()}};
  for (const BenchTable& t : tables) {
    md += markdown(t);
    json["tables"].push_back({{"id", t.id},
                              {"title", t.title},
                              {"columns", t.columns},
                              {"rows", t.rows},
                              {"notes", t.notes},
                              {"data", t.data}});
  }
  // Plots of accuracy against time (plots.h), one per study group. Without them the run is not
  // complete: the tables are still written, the markdown and the page say why the plots are
  // missing, and the exit status is 1.
  std::vector<AccuracyPlot> plots;
  for (const BenchTable& t : tables)
    for (AccuracyPlot& p : studyPlots(t)) plots.push_back(std::move(p));
  std::vector<PlottedFigure> plotted;
  std::string plotError;
  if (!plots.empty()) {
    md +=
        "## Accuracy against time\n\nOne point per precision variant at its median time (the bar spans the fastest and "
        "slowest run); "
        "the Pareto front (the variants no other beats in both time and error) is joined by a line. Timings are of "
        "this run on this machine.\n\n";
    json["plots"] = nlohmann::json::array();
    try {
      for (const AccuracyPlot& p : plots) {
        const PlotFiles files = writeAccuracyPlot(p, options.out / "plots");
        md += plotMarkdown(p, files, "plots");
        json["plots"].push_back(plotJson(p, files, "plots"));
        plotted.push_back({p, files});
      }
    } catch (const PlotError& e) {
      plotError = e.what();
      md += "**Plots not made: " + plotError + "**\n\n";
      json["plots_error"] = plotError;
    }
  }
  io::writeFileAtomically(options.out / "bench.md", md);
  io::writeFileAtomically(options.out / "results.json", json.dump(2) + "\n");
  io::writeFileAtomically(options.out / "index.html", benchHtml(header, tables, plotted, "plots", plotError));
  out << md << "wrote " << (options.out / "bench.md").string() << ", results.json and index.html\n";
  if (!plotError.empty()) {
    std::cerr << "voxref bench: error: plots not made: " << plotError << "\n";
    return 1;
  }
  return 0;
}

}  // namespace voxref::conf
