#include "conformance/modules/catalog.h"
#include "conformance/framework/selection.h"

#include <regex>
#include <set>

#include <gtest/gtest.h>

namespace voxref::conf {
namespace {

TEST(Catalog, IdsAreUniqueDottedLowerSnake) {
  const std::regex form("[a-z0-9_]+(\\.[a-z0-9_]+)+");
  std::set<std::string> ids;
  for (const Case& c : allCases()) {
    EXPECT_TRUE(std::regex_match(c.id, form)) << c.id;
    EXPECT_TRUE(ids.insert(c.id).second) << "duplicate " << c.id;
    EXPECT_FALSE(c.description.empty()) << c.id;
    EXPECT_TRUE(c.run) << c.id;
  }
}

TEST(Catalog, CoversTheIssueMatrix) {
  const auto cases = allCases();
  // Levels 3..8 x three modes x every GL framebuffer format, plus the emulated 12-bit one.
  EXPECT_EQ(selectCases(cases, "sparsegrid.combination.*").size(), 6u * 3u * 5u);
  for (const char* id :
       {"sparsegrid.hard.fig9.unscaled_every_order", "sparsegrid.hard.fig9.scaled", "sparsegrid.hard.nodes.l4",
        "sparsegrid.hard.cell_faces.l4", "sparsegrid.hard.coordinate_one.exact", "sparsegrid.hard.data_extremes.zero",
        "sparsegrid.hard.data_extremes.constant_one", "sparsegrid.hard.large_negative_surpluses.rgba8",
        "sparsegrid.hard.level1", "sparsegrid.hard.level12.rgba8", "sparsegrid.hard.level12.rgba32f"})
    EXPECT_EQ(selectCases(cases, id).size(), 1u) << id;
  // The hard-case catalogue of issue 7 (docs/hard_cases.md): each trap it adds.
  EXPECT_EQ(selectCases(cases, "sparsegrid.hard.float_extremes.*.r32f.*").size(), 4u);
  EXPECT_EQ(selectCases(cases, "sparsegrid.hard.float_extremes.*.r16f.*").size(), 4u);
  EXPECT_EQ(selectCases(cases, "sparsegrid.hard.*_ulps.l4.*").size(), 4u);     // node and mid-cell, linear and nearest
  EXPECT_EQ(selectCases(cases, "timevarying.decode.*.face_ulps").size(), 5u);  // every decoder
  EXPECT_EQ(selectCases(cases, "timevarying.hard.empty_noise_full.*").size(), 5u);  // every decoder
  for (const char* id : {"iso.hard.empty_volume", "iso.hard.full_volume"})
    EXPECT_EQ(selectCases(cases, id).size(), 1u) << id;
}

TEST(Glob, ShellStyle) {
  EXPECT_TRUE(globMatch("sparsegrid*", "sparsegrid.combination.rgba8.l6.xray"));
  EXPECT_TRUE(globMatch("*.l6.*", "sparsegrid.combination.rgba8.l6.xray"));
  EXPECT_FALSE(globMatch("sparsegrid.texture*", "sparsegrid.combination.rgba8.l6.xray"));
  EXPECT_TRUE(globMatch("sparsegrid.combination.rgba1?.l3.mip", "sparsegrid.combination.rgba16.l3.mip"));
}

}  // namespace
}  // namespace voxref::conf
