#include "conformance/bench/study.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace voxref::conf {
namespace {

StudyVariant timed(const std::string& name, double error, double median, double min, double max, double bytes) {
  StudyVariant v;
  v.name = name;
  v.error = error;
  v.time = {median, min, max, 5, false};
  v.memoryBytes = bytes;
  return v;
}

StudyGroup group(bool plotMemory) {
  StudyGroup g{"framebuffer format", "RMSE", "GL frame", "textures", plotMemory, {}, ""};
  g.variants.push_back(timed("rgba8", 0.02, 0.004, 0.003, 0.009, 1000));
  g.variants.push_back(timed("rgba32f", 1e-4, 0.005, 0.0045, 0.006, 4000));
  StudyVariant untimed;
  untimed.name = "rgba12";
  untimed.error = 0.003;
  untimed.missing = "no GL implementation";
  g.variants.push_back(untimed);
  return g;
}

TEST(StudyTable, OneRowPerVariantAndEveryNumberInData) {
  const BenchTable t = studyTable("study.x", "Study, x", {group(false)}, "notes");
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[0][0], "framebuffer format");
  EXPECT_EQ(t.rows[0][1], "rgba8");
  EXPECT_EQ(t.rows[2][3], "n/a");  // not timed
  EXPECT_NE(t.rows[2][2].find("no GL implementation"), std::string::npos);
  const auto& v = t.data["groups"][0]["variants"];
  ASSERT_EQ(v.size(), 3u);
  EXPECT_DOUBLE_EQ(v[0]["error"].get<double>(), 0.02);
  EXPECT_DOUBLE_EQ(v[0]["time"]["min_s"].get<double>(), 0.003);
  EXPECT_DOUBLE_EQ(v[0]["time"]["max_s"].get<double>(), 0.009);
  EXPECT_DOUBLE_EQ(v[1]["memory_bytes"].get<double>(), 4000.0);
  EXPECT_TRUE(v[2]["time"].is_null());
  EXPECT_TRUE(v[2]["memory_bytes"].is_null());  // NaN is written as null, never as a number
}

TEST(StudyPlots, OnePlotPerGroupWithSpreadAndTheUntimedNamed) {
  const BenchTable t = studyTable("study.x", "Study, x", {group(false), group(true)}, "");
  const std::vector<AccuracyPlot> plots = studyPlots(t);
  ASSERT_EQ(plots.size(), 2u);
  EXPECT_EQ(plots[0].id, "study.x.1");
  EXPECT_EQ(plots[1].id, "study.x.2");
  ASSERT_EQ(plots[0].points.size(), 2u);
  EXPECT_DOUBLE_EQ(plots[0].points[0].cost, 0.004);
  EXPECT_DOUBLE_EQ(plots[0].points[0].error, 0.02);
  ASSERT_EQ(plots[0].costSpread.size(), 2u);
  EXPECT_DOUBLE_EQ(plots[0].costSpread[0].first, 0.003);
  EXPECT_DOUBLE_EQ(plots[0].costSpread[0].second, 0.009);
  EXPECT_NE(plots[0].note.find("rgba12"), std::string::npos);
  EXPECT_EQ(plots[0].quantity, "error");
  // A memory group plots bytes.
  EXPECT_EQ(plots[1].quantity, "memory");
  EXPECT_DOUBLE_EQ(plots[1].points[1].error, 4000.0);
}

TEST(StudyPlots, TablesThatAreNotStudiesGiveNone) {
  BenchTable t = studyTable("study.x", "x", {group(false)}, "");
  t.id = "sparsegrid.accuracy";
  EXPECT_TRUE(studyPlots(t).empty());
}

TEST(BytesText, Units) {
  EXPECT_EQ(bytesText(789), "789 B");
  EXPECT_EQ(bytesText(2048), "2 kB");
  EXPECT_EQ(bytesText(3.5 * 1024 * 1024), "3.5 MB");
  EXPECT_EQ(bytesText(std::numeric_limits<double>::quiet_NaN()), "n/a");
}

TEST(Measure, TakesAtLeastTheRunsAskedFor) {
  int calls = 0;
  const Timing t = measure([&] { ++calls; }, 7);
  EXPECT_GE(calls, 7);
  EXPECT_EQ(t.runs, calls);
  EXPECT_LE(t.min, t.median);
  EXPECT_LE(t.median, t.max);
}

TEST(TimingOf, MedianMinMax) {
  const Timing t = timingOf({3.0, 1.0, 2.0});
  EXPECT_EQ(t.median, 2.0);
  EXPECT_EQ(t.min, 1.0);
  EXPECT_EQ(t.max, 3.0);
  EXPECT_EQ(t.runs, 3);
}

}  // namespace
}  // namespace voxref::conf
