#include "conformance/bench/plots.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

#include "conformance/io/atomic_file.h"

extern char** environ;

namespace voxref::conf {
namespace {

std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string quoted(std::string s) {  // a double-quoted string for gnuplot's data file and script
  std::replace(s.begin(), s.end(), '"', '\'');
  return "\"" + s + "\"";
}

std::string gnuplotNumber(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

// Runs gnuplot in `dir` with `args`; throws PlotError with its error output when it fails.
void runGnuplot(const std::filesystem::path& gnuplot, const std::filesystem::path& dir,
                const std::vector<std::string>& args) {
  const std::filesystem::path errFile = dir / ("gnuplot.stderr.tmp" + std::to_string(::getpid()));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addchdir_np(&actions, dir.c_str());
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> all{gnuplot.string()};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, gnuplot.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw PlotError("cannot start " + gnuplot.string() + ": " + std::strerror(rc));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  std::string err;
  try {
    err = io::readWholeFile(errFile);
  } catch (const io::IoError&) {
  }
  std::error_code ec;
  std::filesystem::remove(errFile, ec);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw PlotError(gnuplot.string() + " failed (" +
                    (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status)) : "killed by a signal") +
                    ") on " + (dir / args.back()).string() + (err.empty() ? "" : ": " + err));
}

std::string shortNumber(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.2g", v);
  return b;
}

// One gnuplot label per point, right of it. Labels of points close together on the plot (within
// a quarter decade of error and half a decade of time) are stacked a line apart, so that none is
// written over another.
template <class Drawn>
std::string labels(const AccuracyPlot& plot, const Drawn& drawn, bool logY) {
  double lo = 0.0, hi = 0.0;
  for (const TradeoffPoint& p : plot.points) {
    lo = std::min(lo, drawn(p));
    hi = std::max(hi, drawn(p));
  }
  auto y = [&](const TradeoffPoint& p) {
    return logY ? std::log10(drawn(p)) : (hi > lo ? 4.0 * (drawn(p) - lo) / (hi - lo) : 0.0);
  };
  std::ostringstream out;
  for (std::size_t i = 0; i < plot.points.size(); ++i) {
    int stacked = 0;
    for (std::size_t j = 0; j < i; ++j)
      stacked += std::fabs(y(plot.points[i]) - y(plot.points[j])) < 0.25 &&
                 std::fabs(std::log10(plot.points[i].cost) - std::log10(plot.points[j].cost)) < 0.5;
    out << "set label " << i + 1 << " "
        << quoted(plot.labels[i] + (plot.points[i].error == 0.0 && logY ? " (= 0)" : "")) << " at "
        << gnuplotNumber(plot.points[i].cost) << "," << gnuplotNumber(drawn(plot.points[i])) << " left offset char 1,"
        << shortNumber(0.7 + 1.2 * stacked) << " front\n";
  }
  return out.str();
}

}  // namespace

std::filesystem::path findOnPath(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string d; std::getline(dirs, d, ':');) {
    const std::filesystem::path candidate = std::filesystem::path(d.empty() ? "." : d) / name;
    if (::access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) return candidate;
  }
  return {};
}

PlotFiles writeAccuracyPlot(const AccuracyPlot& plot, const std::filesystem::path& dir) {
  const std::filesystem::path gnuplot = findOnPath("gnuplot");
  if (gnuplot.empty())
    throw PlotError("gnuplot is not on PATH (Debian: apt-get install gnuplot-nox; cmake/setup-debian.sh installs it)");
  io::ensureDirectory(dir);
  PlotFiles f;
  f.png = dir / (plot.id + ".png");
  f.svg = dir / (plot.id + ".svg");
  f.script = dir / (plot.id + ".gp");
  f.data = dir / (plot.id + ".dat");
  f.front = paretoFront(plot.points);
  f.costSummary = frontCostSummary(plot.points, plot.labels, f.front, plot.quantity);

  // A log error axis cannot show 0: zero errors are drawn one decade below the smallest non-zero
  // one (and labelled "= 0"); when every error is 0 the axis is linear.
  double minPositive = 0.0;
  for (const TradeoffPoint& p : plot.points)
    if (p.error > 0.0 && (minPositive == 0.0 || p.error < minPositive)) minPositive = p.error;
  const bool logY = minPositive > 0.0;
  const bool anyZero =
      std::any_of(plot.points.begin(), plot.points.end(), [](const TradeoffPoint& p) { return p.error == 0.0; });
  const double zeroAt = logY ? minPositive / 10.0 : 0.0;
  auto drawn = [&](const TradeoffPoint& p) { return p.error > 0.0 ? p.error : zeroAt; };

  std::ostringstream dat;
  dat << "# " << plot.title
      << "\n# columns: seconds (median), error as drawn, error, on the Pareto front (1/0), min seconds, max seconds, "
         "variant\n"
      << "# index 0: every variant; index 1: the Pareto front in order of time\n";
  for (std::size_t i = 0; i < plot.points.size(); ++i) {
    const bool onFront = std::find(f.front.begin(), f.front.end(), i) != f.front.end();
    const auto spread = i < plot.costSpread.size()
                            ? plot.costSpread[i]
                            : std::pair<double, double>(plot.points[i].cost, plot.points[i].cost);
    dat << gnuplotNumber(plot.points[i].cost) << " " << gnuplotNumber(drawn(plot.points[i])) << " "
        << gnuplotNumber(plot.points[i].error) << " " << onFront << " " << gnuplotNumber(spread.first) << " "
        << gnuplotNumber(spread.second) << " "
        << quoted(plot.labels[i] + (plot.points[i].error == 0.0 && logY ? " (= 0)" : "")) << "\n";
  }
  dat << "\n\n";
  for (std::size_t i : f.front)
    dat << gnuplotNumber(plot.points[i].cost) << " " << gnuplotNumber(drawn(plot.points[i])) << " "
        << gnuplotNumber(plot.points[i].error) << " 1 " << gnuplotNumber(plot.points[i].cost) << " "
        << gnuplotNumber(plot.points[i].cost) << " " << quoted(plot.labels[i]) << "\n";
  if (f.front.empty()) dat << "# (no points)\n";

  const std::string data = plot.id + ".dat";
  std::ostringstream gp;
  gp << "# voxref bench: " << plot.title << "\n# Re-plot from this folder with: gnuplot " << plot.id << ".gp\n"
     << "if (!exists(\"pngout\")) pngout = " << quoted(plot.id + ".png") << "\n"
     << "if (!exists(\"svgout\")) svgout = " << quoted(plot.id + ".svg") << "\n"
     << "set title " << quoted(plot.title) << "\n"
     << "set xlabel " << quoted(plot.xLabel) << "\n"
     << "set ylabel " << quoted(plot.yLabel + (anyZero && logY ? " (0 drawn at " + shortNumber(zeroAt) + ")" : ""))
     << "\n"
     << "set logscale x\n"
     << (logY ? "set logscale y\nset format y \"%.0e\"\n" : "set yrange [*:*]\n")
     << "set grid\nset key top right box opaque\nset offsets graph 0.08, graph 0.45, graph 0.15, graph 0.1\n"
     << "set style line 1 pt 7 ps 1.4 lc rgb \"#1f77b4\"\nset style line 2 pt 6 ps 2.4 lw 2 lc rgb \"#d62728\"\n"
     << labels(plot, drawn, logY) << "set terminal pngcairo size 1000,650 noenhanced font \",10\"\nset output pngout\n"
     << "plot " << quoted(data)
     << " index 0 using 1:2:5:6 with xerrorbars ls 1 title \"variant (bar: min - max time)\", \\\n"
     << "     " << quoted(data) << " index 1 using 1:2 with linespoints ls 2 title \"Pareto front\"\n"
     << "set terminal svg size 1000,650 noenhanced font \",10\"\nset output svgout\nreplot\nunset output\n";

  io::writeFileAtomically(f.data, dat.str());
  io::writeFileAtomically(f.script, gp.str());
  io::AtomicOutput png(f.png), svg(f.svg);
  const std::string pngTmp = png.temporary().filename().string(), svgTmp = svg.temporary().filename().string();
  runGnuplot(gnuplot, dir, {"-e", "pngout='" + pngTmp + "'; svgout='" + svgTmp + "'", f.script.filename().string()});
  for (const auto* out : {&png, &svg})
    if (!std::filesystem::exists(out->temporary()) || std::filesystem::file_size(out->temporary()) == 0)
      throw PlotError("gnuplot wrote no " + out->temporary().string());
  png.commit();
  svg.commit();
  return f;
}

std::string costSentence(const AccuracyPlot& plot, const PlotFiles& files) {
  if (files.costSummary.empty()) return {};
  return std::string(plot.quantity == "error" ? "What each extra bit costs: " : "What each byte saved costs: ") +
         files.costSummary + ".";
}

std::string plotMarkdown(const AccuracyPlot& plot, const PlotFiles& files, const std::string& rel) {
  std::string md = "### " + plot.title + "\n\n![" + plot.title + "](" + rel + "/" + files.png.filename().string() +
                   ")\n\n[SVG](" + rel + "/" + files.svg.filename().string() + "), [gnuplot script](" + rel + "/" +
                   files.script.filename().string() + "), [data](" + rel + "/" + files.data.filename().string() +
                   ")\n\n";
  std::vector<std::string> front;
  for (std::size_t i : files.front) front.push_back(plot.labels[i]);
  if (!files.costSummary.empty())
    md += costSentence(plot, files) + " Pareto front, fastest first: " + joined(front) + ".";
  else
    md += "No variant could be plotted.";
  if (!plot.note.empty()) md += " " + plot.note;
  return md + "\n\n";
}

nlohmann::json plotJson(const AccuracyPlot& plot, const PlotFiles& files, const std::string& rel) {
  nlohmann::json points = nlohmann::json::array();
  for (std::size_t i = 0; i < plot.points.size(); ++i)
    points.push_back({{"variant", plot.labels[i]},
                      {"seconds", plot.points[i].cost},
                      {"error", plot.points[i].error},
                      {"pareto", std::find(files.front.begin(), files.front.end(), i) != files.front.end()}});
  return {{"id", plot.id},
          {"title", plot.title},
          {"x", plot.xLabel},
          {"y", plot.yLabel},
          {"points", points},
          {"png", rel + "/" + files.png.filename().string()},
          {"svg", rel + "/" + files.svg.filename().string()},
          {"script", rel + "/" + files.script.filename().string()},
          {"data", rel + "/" + files.data.filename().string()},
          {"cost_summary", files.costSummary},
          {"note", plot.note}};
}

}  // namespace voxref::conf
