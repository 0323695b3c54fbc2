#include "conformance/report/html_report.h"

#include <map>
#include <sstream>

#include "conformance/report/junit_xml.h"

namespace voxref::conf {
namespace {

std::string esc(const std::string& s) { return xmlEscape(s); }

const char* kStyle = R"css(
body { font: 14px/1.4 system-ui, sans-serif; margin: 2em; color: #222; }
h1 { font-size: 1.6em; } h2 { margin-top: 2em; border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; margin: 0.5em 0; } td, th { border: 1px solid #ddd; padding: 3px 8px; text-align: left; vertical-align: top; }
th { background: #f4f4f4; } .num { text-align: right; font-variant-numeric: tabular-nums; }
.status { font-weight: bold; padding: 1px 6px; border-radius: 3px; color: #fff; }
.pass { background: #2a8a3a; } .warn { background: #c79100; } .fail { background: #c62828; }
.skip { background: #777; } .crash, .timeout { background: #6a1b9a; } .not_run { background: #999; } .info { background: #1565c0; }
.partial { background: #fff3cd; border: 1px solid #c79100; padding: 0.5em 1em; }
figure { display: inline-block; margin: 0 1em 1em 0; } figure img { width: 192px; image-rendering: pixelated; border: 1px solid #ccc; }
pre { background: #f8f8f8; padding: 0.5em; overflow-x: auto; max-height: 24em; }
details { margin: 0.3em 0; } summary { cursor: pointer; }
)css";

std::string badge(std::string_view s) { return "<span class=\"status " + std::string(s) + "\">" + std::string(s) + "</span>"; }

const OracleResult* oracle(const CaseResult& r, const char* name) {
  for (const OracleResult& o : r.oracles)
    if (o.oracle == name) return &o;
  return nullptr;
}

std::string oracleCell(const CaseResult& r, const char* name) {
  const OracleResult* o = oracle(r, name);
  if (!o) return "<td></td>";
  return "<td>" + badge(voxref::conf::name(o->verdict)) + " " + esc(o->summary) + "</td>";
}

}  // namespace

std::string htmlReport(const RunInfo& run, const std::vector<CaseResult>& results) {
  std::ostringstream h;
  h << "<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>voxref conformance report</title><style>" << kStyle
    << "</style></head><body>\n<h1>voxref conformance report</h1>\n";
  if (!run.complete)
    h << "<p class=\"partial\" id=\"partial\">This run was interrupted: the report is partial and holds only the cases that finished.</p>\n";
  h << "<p>Command: <code>" << esc(run.command) << "</code><br>Started " << esc(run.started) << ", finished " << esc(run.finished) << "</p>\n";

  h << "<h2 id=\"driver\">Driver</h2>\n<table>\n";
  const auto& d = run.driver;
  for (const char* key : {"driver", "api", "renderer", "version", "vendor", "glsl_version", "max_3d_texture_size"})
    if (d.contains(key)) h << "<tr><th>" << key << "</th><td>" << esc(d[key].is_string() ? d[key].get<std::string>() : d[key].dump()) << "</td></tr>\n";
  if (d.contains("environment"))
    for (const auto& [k, v] : d["environment"].items()) h << "<tr><th>" << esc(k) << "</th><td>" << esc(v.get<std::string>()) << "</td></tr>\n";
  if (d.contains("cpu_flags")) h << "<tr><th>CPU flags</th><td>" << esc(d["cpu_flags"].dump()) << "</td></tr>\n";
  if (d.contains("profile")) {
    const auto& p = d["profile"];
    h << "<tr><th>profile</th><td><b>" << esc(p["name"].is_null() ? "none (envelope oracle alone)" : p["name"].get<std::string>())
      << "</b> — " << esc(p.value("summary", "")) << "<br><small>" << esc(p.value("chosen", "")) << "</small></td></tr>\n";
  }
  h << "</table>\n";

  // Summary per status and per system.
  const char* statuses[] = {"pass", "warn", "fail", "skip", "crash", "timeout"};
  std::map<std::string, std::map<std::string, int>> bySystem;
  std::map<std::string, int> total;
  for (const CaseResult& r : results) {
    ++bySystem[r.system][std::string(name(r.status))];
    ++total[std::string(name(r.status))];
  }
  h << "<h2 id=\"summary\">Summary</h2>\n<table id=\"summary-table\"><tr><th>system</th>";
  for (const char* s : statuses) h << "<th>" << badge(s) << "</th>";
  h << "<th>cases</th></tr>\n";
  for (const auto& [system, counts] : bySystem) {
    int n = 0;
    h << "<tr><td>" << esc(system) << "</td>";
    for (const char* s : statuses) {
      const int c = counts.count(s) ? counts.at(s) : 0;
      n += c;
      h << "<td class=\"num\">" << c << "</td>";
    }
    h << "<td class=\"num\">" << n << "</td></tr>\n";
  }
  h << "<tr><th>all</th>";
  for (const char* s : statuses) h << "<th class=\"num\" data-status=\"" << s << "\">" << (total.count(s) ? total[s] : 0) << "</th>";
  h << "<th class=\"num\">" << results.size() << "</th></tr></table>\n";

  // Findings: departures from GL semantics, aggregated over cases.
  struct Agg {
    std::string description;
    int cases = 0, casesChanged = 0;
    long samples = 0;
  };
  std::map<std::string, Agg> findings;
  for (const CaseResult& r : results)
    for (const Finding& f : r.findings) {
      Agg& a = findings[f.id];
      a.description = f.description;
      ++a.cases;
      const long changed = f.figures.value("samples_changed", 0L);
      a.casesChanged += changed > 0;
      a.samples += changed;
    }
  h << "<h2 id=\"findings\">Departures from GL semantics</h2>\n";
  if (findings.empty()) {
    h << "<p>None: the profile of this driver models no departure from the GL semantics.</p>\n";
  } else {
    h << "<table><tr><th>finding</th><th>what</th><th>cases where it changes samples</th><th>samples changed</th></tr>\n";
    for (const auto& [id, a] : findings)
      h << "<tr><td><code>" << esc(id) << "</code></td><td>" << esc(a.description) << "</td><td class=\"num\">" << a.casesChanged << " of "
        << a.cases << "</td><td class=\"num\">" << a.samples << "</td></tr>\n";
    h << "</table>\n";
  }

  h << "<h2 id=\"cases\">Cases</h2>\n<table id=\"cases-table\"><tr><th>case</th><th>status</th><th>exact</th><th>envelope</th><th>ideal</th><th>seconds (GL / emulation / reference)</th></tr>\n";
  for (const CaseResult& r : results) {
    char secs[96];
    std::snprintf(secs, sizeof secs, "%.2f / %.2f / %.2f", r.secondsGl, r.secondsEmulation, r.secondsReference);
    h << "<tr data-status=\"" << name(r.status) << "\"><td><a href=\"#" << esc(r.id) << "\">" << esc(r.id) << "</a></td><td>" << badge(name(r.status))
      << "</td>" << oracleCell(r, "exact") << oracleCell(r, "envelope") << oracleCell(r, "ideal") << "<td class=\"num\">" << secs << "</td></tr>\n";
  }
  h << "</table>\n<h2 id=\"details\">Case details</h2>\n";
  for (const CaseResult& r : results) {
    const bool open = r.status == Status::Fail || r.status == Status::Warn || r.status == Status::Crash || r.status == Status::Timeout;
    h << "<details id=\"" << esc(r.id) << "\"" << (open ? " open" : "") << "><summary>" << badge(name(r.status)) << " <code>" << esc(r.id)
      << "</code> — " << esc(r.description) << "</summary>\n";
    if (!r.message.empty()) h << "<p>" << esc(r.message) << "</p>\n";
    const std::pair<const std::string*, const char*> images[] = {{&r.images.rendered, "rendered (GL)"},
                                                                 {&r.images.emulated, "emulated"},
                                                                 {&r.images.reference, "reference (double)"},
                                                                 {&r.images.errorMask, "error mask: red exact, magenta envelope fail, yellow warning"}};
    for (const auto& [path, caption] : images)
      if (!path->empty()) h << "<figure><img src=\"" << esc(*path) << "\" alt=\"" << caption << "\"><figcaption>" << caption << "</figcaption></figure>\n";
    h << "<table><tr><th>oracle</th><th>verdict</th><th>summary</th><th>figures</th></tr>\n";
    for (const OracleResult& o : r.oracles)
      h << "<tr><td>" << esc(o.oracle) << "</td><td>" << badge(name(o.verdict)) << "</td><td>" << esc(o.summary) << "</td><td><pre>"
        << esc(o.figures.dump(1)) << "</pre></td></tr>\n";
    h << "</table>\n";
    if (!r.findings.empty()) {
      h << "<p>Findings:</p><ul>\n";
      for (const Finding& f : r.findings)
        h << "<li><code>" << esc(f.id) << "</code>: " << esc(f.figures.dump()) << "</li>\n";
      h << "</ul>\n";
    }
    h << "<p>Effects simulated: ";
    for (std::size_t i = 0; i < r.effects.size(); ++i) h << (i ? ", " : "") << "<code>" << esc(r.effects[i]) << "</code>";
    h << (r.effects.empty() ? "none" : "") << "</p>\n<details><summary>figures</summary><pre>" << esc(r.figures.dump(1)) << "</pre></details>\n</details>\n";
  }
  h << "</body></html>\n";
  return h.str();
}

}  // namespace voxref::conf
