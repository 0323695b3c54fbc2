#include "conformance/framework/report/results_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "conformance/framework/report/results_json.h"
#include "tests/scratch_folder.h"

namespace voxref::conf {
namespace {

CaseResult everyField() {
  CaseResult r;
  r.id = "timevarying.decode.paper_layout.voxel_centres";
  r.system = "timevarying";
  r.description = "a \"quoted\" description";
  r.status = Status::Timeout;
  r.message = "killed";
  r.stderrText = "line 1\nline 2\n";
  r.oracles = {{"exact", Verdict::Fail, "3 differ", {{"mismatched_pixels", 3}, {"max_abs_diff_lsb", 1}}},
               {"envelope", Verdict::NotRun, "none", nlohmann::json::object()}};
  r.effects = {"texture.nearest", "output.unorm8"};
  r.findings = {{"softpipe.x", "a finding", {{"samples_changed", 2}}}};
  r.figures = {{"planes", 4}};
  r.secondsGl = 0.25;
  r.secondsEmulation = 0.5;
  r.secondsReference = 0.125;
  r.images.rendered = "images/a.png";
  r.images.errorMask = "images/a_mask.png";
  PixelValues p;
  p.x = 3;
  p.y = 4;
  p.k = 5;
  p.oracle = "envelope";
  p.gl = 0.5;
  p.emulated = std::numeric_limits<double>::quiet_NaN();
  p.reference = 0.25;
  p.allowed = std::make_pair(0.125, 0.375);
  r.worstPixels = {p};
  return r;
}

TEST(ResultsReader, CaseJsonRoundTrips) {
  const nlohmann::json written = caseJson(everyField());
  const CaseResult back = caseFromJson(written);
  EXPECT_EQ(caseJson(back), written);
  EXPECT_TRUE(std::isnan(back.worstPixels.at(0).emulated));
  EXPECT_EQ(back.stderrText, "line 1\nline 2\n");
}

TEST(ResultsReader, RejectsWhatIsNotAResultsFile) {
  const test::ScratchFolder dir;
  auto write = [&](const char* name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return dir / name;
  };
  EXPECT_THROW(loadResults(dir / "missing.json"), ResultsFormatError);
  EXPECT_THROW(loadResults(write("not_json.json", "{ cases: ")), ResultsFormatError);
  EXPECT_THROW(loadResults(write("other.json", R"({"format": "something-else"})")), ResultsFormatError);
  EXPECT_THROW(loadResults(write("v2.json", R"({"format": "voxref-results", "format_version": 2, "cases": []})")),
               ResultsFormatError);
  EXPECT_THROW(
      loadResults(write("bad_case.json", R"({"format": "voxref-results", "format_version": 1, "cases": [{"id": 3}]})")),
      ResultsFormatError);
  EXPECT_THROW(loadResults(write("bad_status.json", R"({"format": "voxref-results", "format_version": 1, "cases": [)" +
                                                        caseJson(everyField())
                                                            .dump()
                                                            .replace(caseJson(everyField()).dump().find("\"timeout\""),
                                                                     9, "\"exploded\"") +
                                                        "]}")),
               ResultsFormatError);
  RunInfo run;
  const auto good = write("good.json", resultsJson(run, {everyField()}).dump());
  EXPECT_EQ(loadResults(good).cases.size(), 1u);
}

// Found by tests/fuzz/results_json_fuzz.cpp (tests/fuzz/regressions/results_json): each once let
// an nlohmann exception escape or converted a non-integer into an int (undefined behaviour).
TEST(ResultsReader, FuzzRegressions) {
  auto error = [](const std::string& text) -> std::string {
    try {
      (void)parseResults(text, "r.json");
    } catch (const ResultsFormatError& e) {
      return e.what();
    }
    return "";
  };
  // number_overflow_escapes_parse: nlohmann throws out_of_range (not parse_error) for 1e999.
  EXPECT_NE(error(R"({"format": "voxref-results", "format_version": 1e999})").find("r.json: not JSON"),
            std::string::npos);
  // format_not_a_string_escapes: value("format", "") threw type_error for an object.
  EXPECT_NE(error(R"({"format": {}})").find("not a voxref results file"), std::string::npos);
  EXPECT_NE(error(R"({"format": "voxref-results", "format_version": "1"})").find("results format version \"1\""),
            std::string::npos);
  EXPECT_NE(error(R"({"format": "voxref-results", "format_version": 1e300})").find("results format version"),
            std::string::npos);
  // worst_pixel_null_coordinate_to_int: a null (NaN) or 1e300 pixel coordinate was cast to int.
  nlohmann::json c = caseJson(everyField());
  for (const nlohmann::json& bad :
       {nlohmann::json(nullptr), nlohmann::json(1e300), nlohmann::json(2.5), nlohmann::json(4294967296LL)}) {
    nlohmann::json w = c;
    w["worst_pixels"][0]["x"] = bad;
    EXPECT_THROW((void)caseFromJson(w), ResultsFormatError) << bad.dump();
  }
  nlohmann::json a = c;
  a["worst_pixels"][0]["allowed"] = {"low", 1};
  EXPECT_THROW((void)caseFromJson(a), ResultsFormatError);  // was nlohmann's type_error
  EXPECT_EQ(error(nlohmann::json{{"format", "voxref-results"}, {"format_version", 1}, {"cases", {c}}}.dump()), "");
}

}  // namespace
}  // namespace voxref::conf
