#include <gtest/gtest.h>

#include "conformance/framework/report/junit_xml.h"
#include "conformance/framework/report/results_json.h"

namespace voxref::conf {
namespace {

CaseResult sample(Status s) {
  CaseResult r;
  r.id = "sparsegrid.combination.rgba8.l6.xray";
  r.system = "sparsegrid";
  r.description = "a <case> & more";
  r.status = s;
  r.message = s == Status::Fail ? "exact: 3 of 10 samples differ" : "";
  r.oracles = {{"exact", Verdict::Pass, "0 of 10 samples differ", {{"mismatched_pixels", 0}, {"max_abs_diff_lsb", 0}}},
               {"ideal", Verdict::Info, "max 1", {{"rmse", 0.1}}}};
  r.effects = {"output.unorm8"};
  return r;
}

TEST(ResultsJson, HoldsWhatDesignRequires) {
  RunInfo run;
  run.driver = {{"renderer", "llvmpipe"}};
  run.command = "voxref conform";
  const nlohmann::json j = resultsJson(run, {sample(Status::Pass), sample(Status::Fail)});
  EXPECT_EQ(j["driver"]["renderer"], "llvmpipe");
  EXPECT_EQ(j["summary"]["pass"], 1);
  EXPECT_EQ(j["summary"]["fail"], 1);
  const auto& c = j["cases"][0];
  for (const char* key : {"id", "status", "oracles", "effects", "seconds_gl", "seconds_emulation", "seconds_reference"})
    EXPECT_TRUE(c.contains(key)) << key;
  EXPECT_EQ(c["oracles"]["exact"]["verdict"], "pass");
  EXPECT_EQ(c["oracles"]["exact"]["figures"]["mismatched_pixels"], 0);
}

TEST(JunitXml, FailuresSkipsAndEscaping) {
  CaseResult skip = sample(Status::Skip);
  skip.message = "texture > limit";
  const std::string x = junitXml({sample(Status::Pass), sample(Status::Fail), skip});
  EXPECT_NE(x.find("tests=\"3\" failures=\"1\" errors=\"0\" skipped=\"1\""), std::string::npos) << x;
  EXPECT_NE(x.find("<failure message=\"exact: 3 of 10 samples differ\"/>"), std::string::npos);
  EXPECT_NE(x.find("<skipped message=\"texture &gt; limit\"/>"), std::string::npos);
  EXPECT_EQ(xmlEscape("<a & 'b'>"), "&lt;a &amp; &apos;b&apos;&gt;");
}

TEST(ResultsText, BytesThatAreNotUtf8DoNotStopTheReport) {
  CaseResult r = sample(Status::Crash);
  r.stderrText = std::string("cut in the middle of \xc3");  // a UTF-8 sequence cut short
  const std::string text = resultsText(RunInfo{}, {r});
  const nlohmann::json back = nlohmann::json::parse(text);
  EXPECT_EQ(back["cases"][0]["stderr"].get<std::string>(), "cut in the middle of \xef\xbf\xbd");
}

}  // namespace
}  // namespace voxref::conf
