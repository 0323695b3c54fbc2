#include "conformance/bench/bench_html.h"

#include "conformance/framework/report/html_escape.h"
#include "conformance/framework/report/html_page.h"

namespace voxref::conf {
namespace {

std::string tableHtml(const BenchTable& t) {
  std::string h = "<section class=\"bench-table\" id=\"" + htmlEscape(t.id) + "\"><h2>" + htmlEscape(t.title) +
                  "</h2>\n<table><thead><tr>";
  for (const auto& c : t.columns) h += "<th>" + htmlEscape(c) + "</th>";
  h += "</tr></thead><tbody>\n";
  for (const auto& row : t.rows) {
    h += "<tr>";
    for (const auto& cell : row) h += "<td>" + htmlEscape(cell) + "</td>";
    h += "</tr>\n";
  }
  h += "</tbody></table>\n";
  if (!t.notes.empty()) h += "<p class=\"notes\">" + htmlEscape(t.notes) + "</p>\n";
  return h + "</section>\n";
}

std::string plotHtml(const PlottedFigure& f, const std::string& dir) {
  const std::string base = dir + "/";
  std::string h = "<figure class=\"bench-plot\" id=\"plot-" + htmlEscape(f.plot.id) + "\"><img src=\"" +
                  htmlEscape(base + f.files.svg.filename().string()) + "\" alt=\"" + htmlEscape(f.plot.title) +
                  "\" width=\"1000\" height=\"650\"><figcaption>" + htmlEscape(f.plot.title) + ". ";
  if (const std::string cost = costSentence(f.plot, f.files); !cost.empty()) h += htmlEscape(cost) + " ";
  if (!f.plot.note.empty()) h += htmlEscape(f.plot.note) + " ";
  h += "<a href=\"" + htmlEscape(base + f.files.png.filename().string()) + "\">PNG</a>, <a href=\"" +
       htmlEscape(base + f.files.svg.filename().string()) + "\">SVG</a>, <a href=\"" +
       htmlEscape(base + f.files.script.filename().string()) + "\">gnuplot script</a>, <a href=\"" +
       htmlEscape(base + f.files.data.filename().string()) + "\">data</a></figcaption></figure>\n";
  return h;
}

}  // namespace

std::string benchHtml(const std::string& header, const std::vector<BenchTable>& tables,
                      const std::vector<PlottedFigure>& plots, const std::string& plotsDir,
                      const std::string& plotError) {
  std::string h = pageHead("voxref bench", RunInfo{});
  h += "<h1>voxref bench</h1>\n<p id=\"bench-header\">" + htmlEscape(header) + "</p>\n";
  h += "<nav><ul>";
  for (const BenchTable& t : tables)
    h += "<li><a href=\"#" + htmlEscape(t.id) + "\">" + htmlEscape(t.title) + "</a></li>";
  h += "</ul></nav>\n<h2>Accuracy against time</h2>\n";
  if (!plotError.empty())
    h += "<p id=\"plots-error\" class=\"status fail\">Plots not made: " + htmlEscape(plotError) + "</p>\n";
  h += "<p>One point per precision variant, at its median time; the bar spans the fastest and slowest run. The Pareto "
       "front (the "
       "variants no other beats in both time and error) is joined by a line.</p>\n";
  for (const PlottedFigure& f : plots) h += plotHtml(f, plotsDir);
  for (const BenchTable& t : tables) h += tableHtml(t);
  return h + pageTail("document.documentElement.setAttribute('data-plots', '" + std::to_string(plots.size()) + "');");
}

}  // namespace voxref::conf
