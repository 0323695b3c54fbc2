// Accuracy-against-time plots of `voxref bench`: one per system that has precision variants, one
// point per variant (labelled), the Pareto front joined by a line, as PNG and SVG made by gnuplot.
// Beside the images go the gnuplot script and its data file, so that a user can re-plot
// (`cd DIR/plots && gnuplot ID.gp`). Every file is written atomically (io/atomic_file.h).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/bench/bench.h"
#include "conformance/bench/pareto.h"

namespace voxref::conf {

// The plots could not be made: gnuplot is not on PATH, could not be started, or failed (the
// message names the program and carries its error output).
class PlotError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct AccuracyPlot {
  std::string id;  // file stem: "sparsegrid.accuracy"
  std::string title;
  std::string xLabel;                 // what the cost is: "GL seconds per frame (median)"
  std::string yLabel;                 // what the error is: "RMSE against the double reference"
  std::string quantity = "error";     // what the vertical axis holds: "error" or "memory" (pareto.h)
  std::vector<std::string> labels;    // one per point: the variant
  std::vector<TradeoffPoint> points;  // cost in seconds (> 0), error >= 0
  // Per point, the min and max cost of its repeated runs (drawn as a horizontal bar); empty when
  // there is no spread to show.
  std::vector<std::pair<double, double>> costSpread;
  std::string note;  // variants left out and why; empty when none
};

// The path of the program `name` on PATH, or empty when there is none.
std::filesystem::path findOnPath(const std::string& name);

struct PlotFiles {
  std::filesystem::path png, svg, script, data;  // all in the same folder
  std::vector<std::size_t> front;                // paretoFront(plot.points)
  std::string costSummary;                       // frontCostSummary of the front
};

// Writes dir/ID.dat and dir/ID.gp, runs gnuplot on them into dir/ID.png and dir/ID.svg (each
// through a temporary file renamed when gnuplot succeeded). Creates dir. Throws PlotError when
// gnuplot is missing or fails, io::IoError when a file cannot be written.
PlotFiles writeAccuracyPlot(const AccuracyPlot& plot, const std::filesystem::path& dir);

// "What each extra bit costs: <files.costSummary>." ("What each byte saved costs: ..." for a
// memory plot); empty when the front is empty. The markdown and the bench's page both say it.
std::string costSentence(const AccuracyPlot& plot, const PlotFiles& files);

// The markdown of one plot: the image link (relative to the folder of bench.md, where `dir` is
// `relativeDir`), links to the SVG, script and data, and the "what each extra bit costs" line.
std::string plotMarkdown(const AccuracyPlot& plot, const PlotFiles& files, const std::string& relativeDir);

// The JSON record of one plot for the bench's results.json.
nlohmann::json plotJson(const AccuracyPlot& plot, const PlotFiles& files, const std::string& relativeDir);

}  // namespace voxref::conf
