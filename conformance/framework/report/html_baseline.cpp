#include "conformance/framework/report/html_baseline.h"

#include <sstream>

#include "conformance/framework/report/html_escape.h"
#include "conformance/framework/report/html_page.h"

namespace voxref::conf {
namespace {

std::string text(const nlohmann::json& j, const char* key) {
  return j.is_object() && j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : std::string();
}

const nlohmann::json& list(const nlohmann::json& j, const char* key) {
  static const nlohmann::json empty = nlohmann::json::array();
  return j.contains(key) && j[key].is_array() ? j[key] : empty;
}

void changes(std::ostringstream& h, const nlohmann::json& baseline, const char* key, const char* title) {
  const nlohmann::json& l = list(baseline, key);
  if (l.empty()) return;
  h << "<h3>" << title << " (<span id=\"baseline-" << key << "\">" << l.size()
    << "</span>)</h3>\n<table><tr><th>case</th><th>before</th><th>after</th>"
    << "<th>figures moved</th></tr>\n";
  for (const nlohmann::json& c : l) {
    const std::string id = text(c, "id");
    h << "<tr><td><a href=\"" << htmlEscape(casePageName(id)) << "\"><code>" << htmlEscape(id) << "</code></a></td><td>"
      << badge(text(c, "before")) << "</td><td>" << badge(text(c, "after")) << "</td><td>";
    for (const nlohmann::json& m : list(c, "figures_moved")) {
      const auto num = [&](const char* k) {
        return m.contains(k) && m[k].is_number() ? htmlNumber(m[k].get<double>()) : std::string("—");
      };
      h << htmlEscape(text(m, "oracle") + "." + text(m, "figure")) << ": " << num("before") << " → " << num("after")
        << "<br>";
    }
    h << "</td></tr>\n";
  }
  h << "</table>\n";
}

}  // namespace

std::string baselineSection(const nlohmann::json& baseline) {
  if (!baseline.is_object()) return "";
  std::ostringstream h;
  const bool regressed = baseline.value("regressed", false);
  h << "<section id=\"baseline\"><h2>Compared with the baseline</h2>\n<p>Baseline <code>"
    << htmlEscape(text(baseline, "file")) << "</code>: " << baseline.value("compared", 0) << " case(s) compared. "
    << (regressed ? badge("fail") + " <b>regressed</b>" : badge("pass") + " nothing regressed") << "</p>\n";
  changes(h, baseline, "newly_failing", "Newly failing");
  changes(h, baseline, "newly_warning", "Newly warning");
  changes(h, baseline, "fixed", "Fixed");
  changes(h, baseline, "other_status_changes", "Other changes of status");
  changes(h, baseline, "figures_moved", "Same status, figures moved");
  h << "<p>" << list(baseline, "added").size() << " case(s) only in this run, " << list(baseline, "missing").size()
    << " only in the baseline.</p></section>\n";
  return h.str();
}

}  // namespace voxref::conf
