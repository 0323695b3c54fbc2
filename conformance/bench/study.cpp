#include "conformance/bench/study.h"

#include <cmath>
#include <cstdio>
#include <optional>

namespace voxref::conf {
namespace {

nlohmann::json jsonNumber(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::string errorText(double v) { return std::isnan(v) ? "n/a" : formatNumber("%.3g", v); }

std::string spreadText(const Timing& t) {
  if (t.runs == 0) return "-";
  return formatSeconds({t.min, t.min, t.min, 1, false}) + " - " + formatSeconds({t.max, t.max, t.max, 1, false}) +
         " (" + std::to_string(t.runs) + " runs)";
}

std::optional<double> numberAt(const nlohmann::json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_number()) return std::nullopt;
  const double v = j[key].get<double>();
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

}  // namespace

std::string bytesText(double bytes) {
  char buf[32];
  if (std::isnan(bytes)) return "n/a";
  if (bytes >= 1024.0 * 1024 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f GB", bytes / (1024.0 * 1024 * 1024));
  else if (bytes >= 1024.0 * 1024)
    std::snprintf(buf, sizeof buf, "%.1f MB", bytes / (1024.0 * 1024));
  else if (bytes >= 1024.0)
    std::snprintf(buf, sizeof buf, "%.0f kB", bytes / 1024.0);
  else
    std::snprintf(buf, sizeof buf, "%.0f B", bytes);
  return buf;
}

BenchTable studyTable(const std::string& id, const std::string& title, const std::vector<StudyGroup>& groups,
                      const std::string& notes) {
  BenchTable t;
  t.id = id;
  t.title = title;
  t.columns = {"knob", "variant", "error", "time (median)", "spread (min - max)", "memory"};
  t.notes = notes;
  t.data["groups"] = nlohmann::json::array();
  for (const StudyGroup& g : groups) {
    nlohmann::json variants = nlohmann::json::array();
    for (const StudyVariant& v : g.variants) {
      t.rows.push_back({g.knob, v.name, errorText(v.error) + (v.missing.empty() ? "" : " (" + v.missing + ")"),
                        v.time.runs ? formatSeconds(v.time) : "n/a", spreadText(v.time), bytesText(v.memoryBytes)});
      variants.push_back({{"name", v.name},
                          {"error", jsonNumber(v.error)},
                          {"figures", v.figures},
                          {"time", v.time.runs ? toJson(v.time) : nlohmann::json(nullptr)},
                          {"memory_bytes", jsonNumber(v.memoryBytes)},
                          {"missing", v.missing}});
    }
    t.data["groups"].push_back({{"knob", g.knob},
                                {"error", g.error},
                                {"time", g.time},
                                {"memory", g.memory},
                                {"plot_memory", g.plotMemory},
                                {"variants", variants},
                                {"note", g.note}});
    t.notes += "\n\n" + g.knob + ": error = " + g.error + "; time = " + g.time + "; memory = " + g.memory + "." +
               (g.note.empty() ? "" : " " + g.note);
  }
  return t;
}

std::vector<AccuracyPlot> studyPlots(const BenchTable& table) {
  std::vector<AccuracyPlot> plots;
  if (table.id.rfind("study.", 0) != 0 || !table.data.contains("groups")) return plots;
  int n = 0;
  for (const nlohmann::json& g : table.data["groups"]) {
    const bool byMemory = g.value("plot_memory", false);
    AccuracyPlot p;
    p.id = table.id + "." + std::to_string(++n);
    p.title = table.title + ": " + g.value("knob", std::string("?"));
    p.xLabel = "seconds: " + g.value("time", std::string("?")) + " (median; bar: min - max)";
    p.quantity = byMemory ? "memory" : "error";
    p.yLabel = byMemory ? "bytes: " + g.value("memory", std::string("?")) : g.value("error", std::string("?"));
    std::string left;
    for (const nlohmann::json& v : g["variants"]) {
      const nlohmann::json time = v.value("time", nlohmann::json());
      const double median = time.is_object() ? numberAt(time, "median_s").value_or(0.0) : 0.0;
      const std::optional<double> y = numberAt(v, byMemory ? "memory_bytes" : "error");
      if (median <= 0.0 || !y) {
        left += (left.empty() ? "" : ", ") + v.value("name", std::string("?"));
        continue;
      }
      p.labels.push_back(v.value("name", std::string("?")));
      p.points.push_back({median, *y});
      p.costSpread.push_back({numberAt(time, "min_s").value_or(median), numberAt(time, "max_s").value_or(median)});
    }
    if (!left.empty())
      p.note = "Not plotted (not timed or no " + std::string(byMemory ? "memory" : "error") + " figure): " + left + ".";
    plots.push_back(std::move(p));
  }
  return plots;
}

}  // namespace voxref::conf
