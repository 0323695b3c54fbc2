#include "conformance/framework/report/html_index.h"

#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "conformance/framework/report/html_baseline.h"
#include "conformance/framework/report/html_escape.h"
#include "conformance/framework/report/html_page.h"
#include "conformance/framework/report/judgement_counts.h"
#include "emulation/profile.h"

namespace voxref::conf {
namespace {

constexpr Status kStatuses[] = {Status::Pass, Status::Warn, Status::Fail, Status::Skip, Status::Crash, Status::Timeout};

std::string text(const nlohmann::json& v) {
  return v.is_string() ? v.get<std::string>() : v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

void driverBlock(std::ostringstream& h, const RunInfo& run) {
  h << "<h2 id=\"driver\">Driver and profile</h2>\n<table id=\"driver-table\">\n";
  const nlohmann::json& d = run.driver;
  if (!d.is_object()) {
    h << "<tr><td>no driver information</td></tr></table>\n";
    return;
  }
  for (const char* key : {"driver", "api", "renderer", "version", "vendor", "glsl_version", "max_3d_texture_size"})
    if (d.contains(key)) h << "<tr><th>" << key << "</th><td>" << htmlEscape(text(d[key])) << "</td></tr>\n";
  if (d.contains("environment") && d["environment"].is_object())
    for (const auto& [k, v] : d["environment"].items())
      h << "<tr><th>" << htmlEscape(k) << "</th><td>" << htmlEscape(text(v)) << "</td></tr>\n";
  if (d.contains("cpu_flags")) h << "<tr><th>CPU flags</th><td>" << htmlEscape(text(d["cpu_flags"])) << "</td></tr>\n";
  if (run.execution.is_object() && !run.execution.empty())
    h << "<tr><th>execution</th><td id=\"execution\">" << htmlEscape(text(run.execution)) << "</td></tr>\n";
  if (d.contains("profile") && d["profile"].is_object()) {
    const nlohmann::json& p = d["profile"];
    const bool none = !p.contains("name") || p["name"].is_null();
    h << "<tr><th>profile</th><td id=\"profile\"><b>"
      << htmlEscape(none ? "none: judged by the envelope oracle alone" : text(p["name"])) << "</b>";
    if (p.contains("summary")) h << " — " << htmlEscape(text(p["summary"]));
    if (p.contains("chosen")) h << "<br><small>" << htmlEscape(text(p["chosen"])) << "</small>";
    h << "</td></tr>\n";
  }
  h << "</table>\n";
}

// Per system, which oracle judged the GL output of how many cases, and how many nothing judged
// (framework/report/judgement_counts.h).
void judgementBlock(std::ostringstream& h, const std::vector<CaseResult>& results) {
  h << "<h2 id=\"judgement\">What judged the GL output</h2>\n<p>A case passes only on an oracle that held the GL "
       "output against something and could have failed it here; where none could, the case is a skip, "
       "<q>not judged on this driver</q>, with the reason.</p>\n<table "
       "id=\"judgement-table\"><thead><tr><th>system</th>";
  for (const Judge k : kJudges)
    h << "<th>" << (k == Judge::None ? std::string("not judged") : std::string(name(k))) << "</th>";
  h << "</tr></thead><tbody>\n";
  for (const auto& [system, s] : judgementCounts(results)) {
    h << "<tr><td>" << htmlEscape(system) << "</td>";
    for (const Judge k : kJudges)
      h << "<td class=\"num\" id=\"judged-" << htmlEscape(system) << "-" << name(k) << "\">"
        << (s.judgedBy.count(k) ? s.judgedBy.at(k) : 0) << "</td>";
    h << "</tr>\n";
  }
  h << "</tbody></table>\n";
}

void summaryBlock(std::ostringstream& h, const std::vector<CaseResult>& results) {
  std::map<std::string, std::map<Status, int>> bySystem;
  std::map<Status, int> total;
  for (const CaseResult& r : results) {
    ++bySystem[r.system][r.status];
    ++total[r.status];
  }
  h << "<h2 id=\"summary\">Summary</h2>\n<table id=\"summary-table\"><thead><tr><th>system</th>";
  for (Status s : kStatuses) h << "<th>" << badge(name(s)) << "</th>";
  h << "<th>cases</th></tr></thead><tbody>\n";
  // A count links to the case list filtered to it (the script reads data-system / data-status).
  auto cell = [&](const std::string& tag, const std::string& id, const std::string& system, std::string_view status,
                  int n) {
    h << "<" << tag << " class=\"num\" id=\"" << htmlEscape(id)
      << "\"><a href=\"#cases\" class=\"count\" data-system=\"" << htmlEscape(system) << "\" data-status=\"" << status
      << "\">" << n << "</a></" << tag << ">";
  };
  for (const auto& [system, counts] : bySystem) {
    int n = 0;
    h << "<tr><td>" << htmlEscape(system) << "</td>";
    for (Status s : kStatuses) {
      const int c = counts.count(s) ? counts.at(s) : 0;
      n += c;
      cell("td", "count-" + system + "-" + std::string(name(s)), system, name(s), c);
    }
    cell("td", "count-" + system, system, "", n);
    h << "</tr>\n";
  }
  h << "<tr><th>all</th>";
  for (Status s : kStatuses) cell("th", "count-" + std::string(name(s)), "", name(s), total.count(s) ? total[s] : 0);
  cell("th", "count-cases", "", "", static_cast<int>(results.size()));
  h << "</tr></tbody></table>\n";
}

// What the run can say about departures when no finding was made: that depends on whether a
// profile (a model of the driver's arithmetic and of its named departures) was used at all.
std::string noFindingText(const RunInfo& run) {
  const nlohmann::json& p =
      run.driver.is_object() ? run.driver.value("profile", nlohmann::json::object()) : nlohmann::json::object();
  const nlohmann::json name = p.is_object() ? p.value("name", nlohmann::json()) : nlohmann::json();
  if (!name.is_string())
    return "Unknown: this run used no precision profile, so no model of the driver's departures from the GL semantics "
           "was applied; "
           "none were measured on GL directly either.";
  const emu::PrecisionProfile* profile = emu::findProfile(name.get<std::string>());
  std::string modelled;
  for (const emu::Departure& d : profile ? emu::departuresFromGlSemantics(*profile) : std::vector<emu::Departure>{})
    modelled += std::string(modelled.empty() ? "" : ", ") + "<code>" + htmlEscape(std::string(d.id)) + "</code>";
  return modelled.empty() ? "None: the profile " + htmlEscape(name.get<std::string>()) +
                                " models no departure from the GL semantics, and none "
                                "was measured on GL directly."
                          : "None in these cases: the profile " + htmlEscape(name.get<std::string>()) + " models " +
                                modelled + ", and no case of this run met one.";
}

void findingsBlock(std::ostringstream& h, const RunInfo& run, const std::vector<CaseResult>& results) {
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
      const nlohmann::json changedJson =
          f.figures.is_object() ? f.figures.value("samples_changed", nlohmann::json(0)) : nlohmann::json(0);
      const long changed = changedJson.is_number() ? changedJson.get<long>() : 0;
      a.casesChanged += changed > 0;
      a.samples += changed;
    }
  h << "<h2 id=\"findings\">Departures from GL semantics</h2>\n";
  if (findings.empty()) {
    h << "<p>" << noFindingText(run) << "</p>\n";
    return;
  }
  h << "<table><tr><th>finding</th><th>what</th><th>cases where it changes samples</th><th>samples changed</th></tr>\n";
  for (const auto& [id, a] : findings)
    h << "<tr><td><code>" << htmlEscape(id) << "</code></td><td>" << htmlEscape(a.description)
      << "</td><td class=\"num\">" << a.casesChanged << " of " << a.cases << "</td><td class=\"num\">" << a.samples
      << "</td></tr>\n";
  h << "</table>\n";
}

void filterBlock(std::ostringstream& h, const std::vector<CaseResult>& results) {
  std::set<std::string> systems;
  for (const CaseResult& r : results) systems.insert(r.system);
  h << "<form class=\"filters\" id=\"filters\" onsubmit=\"return false\"><b>Show</b> ";
  for (Status s : kStatuses)
    h << "<label><input type=\"checkbox\" name=\"status\" value=\"" << name(s) << "\" checked> " << name(s)
      << "</label>";
  h << "<label>system <select id=\"filter-system\"><option value=\"\">all</option>";
  for (const std::string& s : systems)
    h << "<option value=\"" << htmlEscape(s) << "\">" << htmlEscape(s) << "</option>";
  h << "</select></label><label>id contains <input type=\"search\" id=\"filter-id\" placeholder=\"e.g. "
       "rgba8.l6\"></label>"
    << "<span><b id=\"shown-count\">" << results.size() << "</b> of " << results.size()
    << " cases shown</span></form>\n";
}

void casesBlock(std::ostringstream& h, const std::vector<CaseResult>& results) {
  h << "<h2 id=\"cases\">Cases</h2>\n";
  filterBlock(h, results);
  h << "<table "
       "id=\"cases-table\"><thead><tr><th>case</th><th>system</th><th>status</th><th>oracles</th><th>message</th>"
       "<th>seconds (GL / emulation / reference)</th></tr></thead><tbody>\n";
  for (const CaseResult& r : results) {
    char secs[96];
    std::snprintf(secs, sizeof secs, "%.2f / %.2f / %.2f", r.secondsGl, r.secondsEmulation, r.secondsReference);
    h << "<tr data-id=\"" << htmlEscape(r.id) << "\" data-status=\"" << name(r.status) << "\" data-system=\""
      << htmlEscape(r.system) << "\"><td><a href=\"" << htmlEscape(casePageName(r.id)) << "\"><code>"
      << htmlEscape(r.id) << "</code></a></td><td>" << htmlEscape(r.system) << "</td><td>" << badge(name(r.status))
      << "</td><td>";
    for (const OracleResult& o : r.oracles)
      h << "<span class=\"status " << name(o.verdict) << "\" title=\""
        << htmlEscape(std::string(name(o.verdict)) + ": " + o.summary) << "\">" << htmlEscape(o.oracle) << "</span> ";
    h << "</td><td class=\"message\">"
      << htmlEscape(r.message.size() > 300 ? r.message.substr(0, 300) + " …" : r.message) << "</td><td class=\"num\">"
      << secs << "</td></tr>\n";
  }
  h << "</tbody></table>\n";
}

// Filters the case rows; a click on a count in the summary filters to that system and status.
const char* kFilterScript = R"js(
var rows = Array.prototype.slice.call(document.querySelectorAll('#cases-table tbody tr'));
var boxes = Array.prototype.slice.call(document.querySelectorAll('#filters input[name=status]'));
var system = document.getElementById('filter-system');
var idText = document.getElementById('filter-id');
var shown = document.getElementById('shown-count');
function apply() {
  var wanted = {};
  boxes.forEach(function (b) { wanted[b.value] = b.checked; });
  var s = system.value, t = idText.value.trim().toLowerCase(), n = 0;
  rows.forEach(function (r) {
    var show = wanted[r.dataset.status] && (!s || r.dataset.system === s) && (!t || r.dataset.id.toLowerCase().indexOf(t) >= 0);
    r.hidden = !show;
    if (show) ++n;
  });
  shown.textContent = String(n);
}
boxes.forEach(function (b) { b.addEventListener('change', apply); });
system.addEventListener('change', apply);
idText.addEventListener('input', apply);
Array.prototype.slice.call(document.querySelectorAll('a.count')).forEach(function (a) {
  a.addEventListener('click', function () {
    var st = a.dataset.status;
    boxes.forEach(function (b) { b.checked = !st || b.value === st; });
    system.value = a.dataset.system;
    idText.value = '';
    apply();
  });
});
apply();
)js";

}  // namespace

std::string htmlIndex(const RunInfo& run, const std::vector<CaseResult>& results) {
  std::ostringstream h;
  h << pageHead("voxref conformance report", run) << "<h1>voxref conformance report</h1>\n<p>Command: <code>"
    << htmlEscape(run.command) << "</code><br>Started " << htmlEscape(run.started) << ", finished "
    << htmlEscape(run.finished) << "</p>\n";
  if (!run.notRun.empty()) {
    h << "<details id=\"not-run\"><summary>" << run.notRun.size() << " selected case(s) did not run</summary><ul>";
    for (const std::string& id : run.notRun) h << "<li><code>" << htmlEscape(id) << "</code></li>";
    h << "</ul></details>\n";
  }
  driverBlock(h, run);
  summaryBlock(h, results);
  judgementBlock(h, results);
  h << baselineSection(run.baseline);
  findingsBlock(h, run, results);
  casesBlock(h, results);
  h << pageTail(kFilterScript);
  return h.str();
}

}  // namespace voxref::conf
