#include "conformance/framework/report/html_case_page.h"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>

#include "conformance/framework/report/html_escape.h"
#include "conformance/framework/report/html_page.h"
#include "conformance/framework/report/html_worst_pixels.h"

namespace voxref::conf {
namespace {

const std::string kToRoot = "../";  // from cases/ to the report directory

std::string dump(const nlohmann::json& j, int indent = -1) {
  return j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

double number(const nlohmann::json& j) { return j.is_number() ? j.get<double>() : std::nan(""); }

// The envelope's "failures": [{"sample": [i, j, k], "value": v, "allowed": [lo, hi]}, ...].
bool isFailureList(const nlohmann::json& j) {
  if (!j.is_array() || j.empty()) return false;
  for (const nlohmann::json& f : j)
    if (!f.is_object() || !f.contains("allowed") || !f["allowed"].is_array() || f["allowed"].size() != 2) return false;
  return true;
}

std::string failureTable(const nlohmann::json& failures) {
  std::ostringstream h;
  h << "<table class=\"failures\"><tr><th>sample</th><th>value</th><th>allowed interval</th><th>outside by</th></tr>\n";
  for (const nlohmann::json& f : failures) {
    const double v = f.contains("value") ? number(f["value"]) : std::nan("");
    const double lo = number(f["allowed"][0]), hi = number(f["allowed"][1]);
    const double outside = v < lo ? lo - v : v > hi ? v - hi : 0.0;
    h << "<tr><td>" << htmlEscape(f.contains("sample") ? dump(f["sample"]) : "") << "</td><td class=\"num\">"
      << htmlNumber(v) << "</td><td class=\"num\">[" << htmlNumber(lo) << ", " << htmlNumber(hi)
      << "]</td><td class=\"num\">" << htmlNumber(outside) << "</td></tr>\n";
  }
  h << "</table>";
  return h.str();
}

// Scalars inline, failure lists as tables, anything else nested as JSON.
std::string figuresHtml(const nlohmann::json& figures) {
  if (!figures.is_object()) return "<pre>" + htmlEscape(dump(figures, 1)) + "</pre>";
  if (figures.empty()) return "";
  std::ostringstream h;
  h << "<table class=\"figures\">";
  for (const auto& [key, value] : figures.items()) {
    h << "<tr><th>" << htmlEscape(key) << "</th><td>";
    if (value.is_number())
      h << "<span class=\"num\">" << htmlNumber(value.get<double>()) << "</span>";
    else if (value.is_string())
      h << htmlEscape(value.get<std::string>());
    else if (isFailureList(value))
      h << failureTable(value);
    else if (value.is_primitive())
      h << htmlEscape(dump(value));
    else
      h << "<details><summary>" << htmlEscape(value.is_array() ? std::to_string(value.size()) + " entries" : "details")
        << "</summary><pre>" << htmlEscape(dump(value, 1)) << "</pre></details>";
    h << "</td></tr>";
  }
  h << "</table>";
  return h.str();
}

void oraclesBlock(std::ostringstream& h, const CaseResult& r) {
  h << "<h2 id=\"oracles\">Oracles</h2>\n";
  if (r.oracles.empty()) {
    h << "<p>No oracle judged this case.</p>\n";
    return;
  }
  h << "<table "
       "id=\"oracle-table\"><thead><tr><th>oracle</th><th>verdict</th><th>summary</th><th>figures</th></tr></"
       "thead><tbody>\n";
  for (const OracleResult& o : r.oracles)
    h << "<tr data-oracle=\"" << htmlEscape(o.oracle) << "\"><td>" << htmlEscape(o.oracle) << "</td><td>"
      << badge(name(o.verdict)) << "</td><td class=\"message\">" << htmlEscape(o.summary) << "</td><td>"
      << figuresHtml(o.figures) << "</td></tr>\n";
  h << "</tbody></table>\n";
}

void effectsAndFindings(std::ostringstream& h, const CaseResult& r) {
  h << "<h2 id=\"effects\">Effects simulated</h2>\n";
  if (r.effects.empty()) {
    h << "<p>None (no emulation ran, or the scene calls for no effect).</p>\n";
  } else {
    h << "<ul id=\"effects-list\">";
    for (const std::string& e : r.effects) h << "<li><code>" << htmlEscape(e) << "</code></li>";
    h << "</ul>\n";
  }
  if (r.findings.empty()) return;
  h << "<h2 id=\"findings\">Departures from GL "
       "semantics</h2>\n<table><tr><th>finding</th><th>what</th><th>figures</th></tr>\n";
  for (const Finding& f : r.findings)
    h << "<tr><td><code>" << htmlEscape(f.id) << "</code></td><td>" << htmlEscape(f.description) << "</td><td>"
      << figuresHtml(f.figures) << "</td></tr>\n";
  h << "</table>\n";
}

void imagesBlock(std::ostringstream& h, const CaseResult& r) {
  h << "<h2 id=\"images\">Images</h2>\n";
  const std::pair<const std::string*, const char*> images[] = {
      {&r.images.rendered, "rendered (GL)"},
      {&r.images.emulated, "emulated"},
      {&r.images.reference, "reference (double)"},
      {&r.images.errorMask, "error mask: red exact mismatch, magenta envelope failure, yellow warning"}};
  bool any = false;
  for (const auto& [path, caption] : images) any = any || !path->empty();
  if (!any) {
    h << "<p>This case wrote no images (cases write them when they fail or warn, or with "
         "<code>--all-images</code>).</p>\n";
    return;
  }
  h << "<div class=\"images\">";
  for (const auto& [path, caption] : images)
    if (!path->empty())
      h << "<figure><a href=\"" << htmlEscape(kToRoot + *path) << "\"><img src=\"" << htmlEscape(kToRoot + *path)
        << "\" alt=\"" << caption << "\"></a><figcaption>" << caption << "</figcaption></figure>";
  h << "</div>\n";
}

}  // namespace

std::string htmlCasePage(const RunInfo& run, const CaseResult& r) {
  std::ostringstream h;
  h << pageHead(r.id + " — voxref", run) << "<p><a href=\"" << kToRoot << "index.html\">← all cases</a></p>\n<h1><code>"
    << htmlEscape(r.id) << "</code> <span id=\"case-status\" data-status=\"" << name(r.status) << "\">"
    << badge(name(r.status)) << "</span></h1>\n<p>" << htmlEscape(r.description)
    << "</p>\n<table><tr><th>system</th><td>" << htmlEscape(r.system)
    << "</td></tr><tr><th>judged on GL by</th><td id=\"judged-by\">" << name(r.judgedBy) << "</td></tr>";
  char secs[96];
  std::snprintf(secs, sizeof secs, "%.3f / %.3f / %.3f", r.secondsGl, r.secondsEmulation, r.secondsReference);
  h << "<tr><th>seconds (GL / emulation / reference)</th><td class=\"num\">" << secs << "</td></tr>";
  if (r.timings.is_object() && !r.timings.empty())
    h << "<tr><th>other times (wall clock)</th><td>" << figuresHtml(r.timings) << "</td></tr>";
  h << "</table>\n";
  const bool died = r.status == Status::Crash || r.status == Status::Timeout;
  if (!r.message.empty())
    h << (died ? "<pre id=\"message\">" : "<p id=\"message\" class=\"message\">") << htmlEscape(r.message)
      << (died ? "</pre>\n" : "</p>\n");
  if (died || !r.stderrText.empty()) {
    h << "<h2 id=\"output\">Output of the case's process</h2>\n";
    if (r.stderrText.empty())
      h << "<p>None was kept.</p>\n";
    else
      h << "<pre id=\"stderr\">" << htmlEscape(r.stderrText) << "</pre>\n";
  }
  oraclesBlock(h, r);
  effectsAndFindings(h, r);
  imagesBlock(h, r);
  h << worstPixelsSection(r, kToRoot);
  h << "<h2 id=\"figures\">Figures of the case</h2>\n" << figuresHtml(r.figures) << "\n";
  h << pageTail("");
  return h.str();
}

}  // namespace voxref::conf
