#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "conformance/framework/report/html_case_page.h"
#include "conformance/framework/report/html_escape.h"
#include "conformance/framework/report/html_index.h"
#include "conformance/framework/report/html_report.h"
#include "conformance/io/atomic_file.h"
#include "tests/scratch_folder.h"

namespace voxref::conf {
namespace {

bool has(const std::string& page, const std::string& what) { return page.find(what) != std::string::npos; }

std::size_t count(const std::string& page, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = page.find(what); at != std::string::npos; at = page.find(what, at + what.size())) ++n;
  return n;
}

CaseResult result(std::string id, std::string system, Status s) {
  CaseResult r;
  r.id = std::move(id);
  r.system = std::move(system);
  r.description = "checks <b>bold</b> & 'quotes'";
  r.status = s;
  r.oracles = {{"exact",
                s == Status::Fail ? Verdict::Fail : Verdict::Pass,
                "0 of 10 samples differ",
                {{"mismatched_pixels", 0}}}};
  r.effects = {"output.unorm8"};
  return r;
}

RunInfo run(bool complete) {
  RunInfo r;
  r.driver = {{"renderer", "llvmpipe <LLVM>"}, {"profile", {{"name", "llvmpipe"}}}};
  r.command = "voxref conform";
  r.complete = complete;
  return r;
}

// Every page is one document with balanced script elements and the self-check in place.
void expectWellFramed(const std::string& page) {
  EXPECT_EQ(page.rfind("<!doctype html>", 0), 0u);
  EXPECT_TRUE(page.ends_with("</body></html>\n"));
  EXPECT_EQ(count(page, "<script>"), count(page, "</script>"));
  EXPECT_EQ(count(page, "<script"), 2u) << "the self-check and the page's own script, nothing injected";
  EXPECT_TRUE(has(page, "id=\"js-errors\""));
  EXPECT_TRUE(has(page, "data-report-ready"));
  EXPECT_FALSE(has(page, "http://"));
  EXPECT_FALSE(has(page, "https://"));
}

TEST(HtmlEscape, EscapesMarkupControlsAndBrokenUtf8) {
  EXPECT_EQ(htmlEscape("<a href=\"x\">'&'</a>"), "&lt;a href=&quot;x&quot;&gt;&#39;&amp;&#39;&lt;/a&gt;");
  EXPECT_EQ(htmlEscape("tab\tnl\nbell\x07 del\x7f"), "tab\tnl\nbell  del ");
  EXPECT_EQ(htmlEscape("µs → ok"), "µs → ok");                                    // valid UTF-8 stays
  EXPECT_EQ(htmlEscape("bad \xff\xc3 end"), "bad \xef\xbf\xbd\xef\xbf\xbd end");  // invalid bytes become U+FFFD
  EXPECT_EQ(htmlEscape("\xed\xa0\x80"), "\xef\xbf\xbd\xef\xbf\xbd\xef\xbf\xbd");  // a surrogate is not UTF-8
}

TEST(HtmlEscape, CasePageNamesStayInCasesAndAreSafeUrls) {
  EXPECT_EQ(casePageName("sparsegrid.combination.rgba8.l6.xray"), "cases/sparsegrid.combination.rgba8.l6.xray.html");
  EXPECT_EQ(casePageName("../x y/<z>"), "cases/.._x_y__z_.html");
}

TEST(HtmlIndex, CountsPerStatusAndSystemFiltersAndLinks) {
  const std::string h =
      htmlIndex(run(true), {result("a.one", "sparsegrid", Status::Pass), result("a.two", "sparsegrid", Status::Fail),
                            result("b.one", "iso", Status::Pass), result("b.two", "iso", Status::Skip)});
  expectWellFramed(h);
  EXPECT_TRUE(
      has(h, "id=\"count-pass\"><a href=\"#cases\" class=\"count\" data-system=\"\" data-status=\"pass\">2</a>"))
      << h;
  EXPECT_TRUE(
      has(h, "id=\"count-fail\"><a href=\"#cases\" class=\"count\" data-system=\"\" data-status=\"fail\">1</a>"));
  EXPECT_TRUE(
      has(h, "id=\"count-crash\"><a href=\"#cases\" class=\"count\" data-system=\"\" data-status=\"crash\">0</a>"));
  EXPECT_TRUE(has(
      h, "id=\"count-iso-skip\"><a href=\"#cases\" class=\"count\" data-system=\"iso\" data-status=\"skip\">1</a>"));
  EXPECT_TRUE(has(h,
                  "id=\"count-sparsegrid-fail\"><a href=\"#cases\" class=\"count\" data-system=\"sparsegrid\" "
                  "data-status=\"fail\">1</a>"));
  EXPECT_TRUE(has(h, ">4</a></th>"));  // count-cases
  EXPECT_TRUE(has(h, "<a href=\"cases/a.two.html\">"));
  EXPECT_TRUE(has(h, "<tr data-id=\"b.two\" data-status=\"skip\" data-system=\"iso\">"));
  EXPECT_TRUE(has(h, "id=\"filter-system\""));
  EXPECT_TRUE(has(h, "<option value=\"iso\">iso</option>"));
  EXPECT_TRUE(has(h, "id=\"filter-id\""));
  EXPECT_TRUE(has(h, "llvmpipe &lt;LLVM&gt;"));
  EXPECT_FALSE(has(h, "id=\"partial\""));
}

TEST(HtmlIndex, EscapesEveryTextAndMarksPartialRuns) {
  CaseResult evil = result("x.evil\"><script>alert(1)</script>", "sys<tem>", Status::Fail);
  evil.message = "</td></table><script>alert(2)</script>";
  evil.oracles[0].summary = "\" onmouseover=\"alert(3)";
  const std::string h = htmlIndex(run(false), {evil});
  expectWellFramed(h);
  EXPECT_TRUE(has(h, "id=\"partial\">partial report: the run was interrupted"));
  EXPECT_FALSE(has(h, "alert(1)</script>"));
  EXPECT_FALSE(has(h, "<script>alert"));
  EXPECT_FALSE(has(h, "\" onmouseover"));
  EXPECT_TRUE(has(h, "&lt;/td&gt;&lt;/table&gt;&lt;script&gt;alert(2)&lt;/script&gt;"));
  EXPECT_TRUE(has(h, "href=\"cases/x.evil___script_alert_1___script_.html\""));
  const std::string page = htmlCasePage(run(false), evil);
  expectWellFramed(page);
  EXPECT_TRUE(has(page, "id=\"partial\""));
  EXPECT_FALSE(has(page, "<script>alert"));
}

TEST(HtmlIndex, SaysWhyARunIsPartialAndWhatDidNotRun) {
  RunInfo interrupted = run(false);
  interrupted.interruptedBy = "SIGINT";
  interrupted.notRun = {"b.three", "b.<four>"};
  const std::string h = htmlIndex(interrupted, {result("a.one", "sparsegrid", Status::Pass)});
  EXPECT_TRUE(has(h,
                  "partial report: the run was interrupted (SIGINT); it holds only the cases that finished; 2 selected "
                  "case(s) did not run."));
  EXPECT_TRUE(has(h, "<li><code>b.&lt;four&gt;</code></li>"));
  RunInfo snapshot = run(false);
  snapshot.running = true;
  EXPECT_TRUE(has(htmlIndex(snapshot, {}), "partial report: the run is still going on"));
  expectWellFramed(htmlIndex(snapshot, {}));
}

TEST(HtmlIndex, ShowsTheBaselineComparison) {
  RunInfo withBaseline = run(true);
  withBaseline.baseline = {
      {"file", "old/results.json"},
      {"regressed", true},
      {"compared", 2},
      {"newly_failing",
       {{{"id", "a.two"},
         {"before", "pass"},
         {"after", "fail"},
         {"figures_moved", {{{"oracle", "exact"}, {"figure", "mismatched_pixels"}, {"before", 0}, {"after", 3}}}}}}},
      {"added", {"a.three"}}};
  const std::string h = htmlIndex(withBaseline, {result("a.two", "sparsegrid", Status::Fail)});
  expectWellFramed(h);
  EXPECT_TRUE(has(h, "<b>regressed</b>"));
  EXPECT_TRUE(has(h, "<span id=\"baseline-newly_failing\">1</span>"));
  EXPECT_TRUE(has(h, "exact.mismatched_pixels: 0 → 3"));
  EXPECT_TRUE(has(h, "1 case(s) only in this run, 0 only in the baseline."));
  EXPECT_FALSE(has(htmlIndex(run(true), {}), "id=\"baseline\""));
}

TEST(HtmlCasePage, CrashShowsItsOutputAndNoImages) {
  CaseResult crash = result("sparsegrid.control.crash", "sparsegrid", Status::Crash);
  crash.oracles.clear();
  crash.effects.clear();
  crash.message = "the case's process was killed by signal 11 (SIGSEGV)";
  crash.stderrText = "free(): invalid pointer <0x55d0>\n\xff";
  const std::string h = htmlCasePage(run(true), crash);
  expectWellFramed(h);
  EXPECT_TRUE(has(h, "id=\"case-status\" data-status=\"crash\""));
  EXPECT_TRUE(has(h, "<pre id=\"message\">the case&#39;s process was killed by signal 11 (SIGSEGV)</pre>"));
  EXPECT_TRUE(has(h, "<pre id=\"stderr\">free(): invalid pointer &lt;0x55d0&gt;\n\xef\xbf\xbd</pre>"));
  EXPECT_TRUE(has(h, "No oracle judged this case."));
  EXPECT_TRUE(has(h, "This case wrote no images"));
  EXPECT_TRUE(has(h, "The case singled out no pixel."));
  EXPECT_FALSE(has(h, "<img"));

  CaseResult timeout = crash;
  timeout.status = Status::Timeout;
  timeout.stderrText.clear();
  EXPECT_TRUE(has(htmlCasePage(run(true), timeout), "None was kept."));
}

TEST(HtmlCasePage, WorstPixelsAreMagnifiedWithValuesAndIntervals) {
  CaseResult r = result("sparsegrid.combination.rgba8.l4.mip", "sparsegrid", Status::Fail);
  r.images = {"images/c.rendered.png", "images/c.emulated.png", "images/c.reference.png", "images/c.error_mask.png"};
  r.worstPixels.push_back({12, 3, 7, "envelope", 0.25, 0.5, 0.375, std::make_pair(0.3, 0.45)});
  r.worstPixels.push_back({0, 47, 0, "exact", 1.0, std::nan(""), 1.0, std::nullopt});
  r.oracles.push_back(
      {"envelope",
       Verdict::Fail,
       "1 of 10 samples outside",
       {{"fail", 1},
        {"failures", nlohmann::json::array({{{"sample", {12, 3, 7}}, {"value", 0.25}, {"allowed", {0.3, 0.45}}}})}}});
  const std::string h = htmlCasePage(run(true), r);
  expectWellFramed(h);
  EXPECT_EQ(count(h, "<tr class=\"worst-pixel\""), 2u);
  EXPECT_TRUE(has(h, "<tr class=\"worst-pixel\" data-x=\"12\" data-y=\"3\" data-k=\"7\">"));
  // GL, emulated, reference, the two differences, the interval and that GL lies outside it.
  EXPECT_TRUE(has(
      h,
      "<td class=\"num\">0.25</td><td class=\"num\">0.5</td><td class=\"num\">0.375</td><td class=\"num\">-0.25</td>"
      "<td class=\"num\">-0.125</td><td>[0.3, 0.45] <span class=\"status fail\">GL outside</span>"))
      << h;
  EXPECT_TRUE(has(h,
                  "<td class=\"num\">1</td><td class=\"num\">—</td><td class=\"num\">1</td><td class=\"num\">—</td><td "
                  "class=\"num\">0</td><td>—</td>"));
  // Crops: the image anchored by its bottom edge so that GL row y is the centre row (no flip needed).
  EXPECT_TRUE(has(
      h, "src=\"../images/c.error_mask.png\" alt=\"error mask around the pixel\" style=\"left:-56px;bottom:16px\""));
  EXPECT_TRUE(has(h, "src=\"../images/c.rendered.png\" alt=\"GL around the pixel\" style=\"left:40px;bottom:-336px\""));
  EXPECT_EQ(count(h, "class=\"crop\""), 8u);
  // The four images side by side, and the envelope's failures with their allowed intervals.
  EXPECT_TRUE(has(h, "<img src=\"../images/c.reference.png\" alt=\"reference (double)\">"));
  EXPECT_TRUE(has(
      h, "<td>[12,3,7]</td><td class=\"num\">0.25</td><td class=\"num\">[0.3, 0.45]</td><td class=\"num\">0.05</td>"));
  EXPECT_TRUE(has(h, "<li><code>output.unorm8</code></li>"));
}

TEST(HtmlReport, WritesIndexAndCasePages) {
  const test::ScratchFolder scratch;
  const std::filesystem::path dir = scratch / "report";  // the report makes its folder
  writeHtmlReport(dir, run(false),
                  {result("a.one", "sparsegrid", Status::Pass), result("a/two", "sparsegrid", Status::Fail)});
  const std::string index = io::readWholeFile(dir / "index.html");
  EXPECT_TRUE(has(index, "id=\"partial\""));
  EXPECT_TRUE(has(io::readWholeFile(dir / "cases/a.one.html"), "id=\"case-status\" data-status=\"pass\""));
  EXPECT_TRUE(has(io::readWholeFile(dir / "cases/a_two.html"), "id=\"case-status\" data-status=\"fail\""));
  std::size_t files = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) files += e.is_regular_file();
  EXPECT_EQ(files, 3u) << "no temporary file left behind";
}

// Without a profile nothing modelled the driver's departures: the index says they are unknown, never
// that there are none. With one, it names what the profile models.
TEST(HtmlIndex, DeparturesAreUnknownWithoutAProfile) {
  RunInfo noProfile = run(true);
  noProfile.driver["profile"] = {{"name", nullptr}, {"chosen", "named on the command line: envelope"}};
  const std::string page = htmlIndex(noProfile, {result("a.b", "sparsegrid", Status::Pass)});
  EXPECT_TRUE(has(page, "Unknown: this run used no precision profile")) << page;
  EXPECT_FALSE(has(page, "models no departure"));
  RunInfo softpipe = run(true);
  softpipe.driver["profile"] = {{"name", "softpipe"}};
  EXPECT_TRUE(
      has(htmlIndex(softpipe, {result("a.b", "sparsegrid", Status::Pass)}), "softpipe.texture.tile_cache_aliasing"));
  EXPECT_TRUE(has(htmlIndex(run(true), {result("a.b", "sparsegrid", Status::Pass)}),
                  "None: the profile llvmpipe models no departure"));
}

}  // namespace
}  // namespace voxref::conf
