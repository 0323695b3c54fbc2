// The isovalue mask against the table it is made from: for its isovalue and for others, every
// grid point gets the table's answer (DiamondBounds::holds on the entry's min and max).
#include "reference/iso/isovalue_mask.h"

#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "tests/reference/iso/iso_test_fields.h"
#include "tests/reference/leb/grid_points.h"

namespace voxref::ref {
namespace {

// Every grid point: the mask's answer for `asked` is min <= asked <= max of its entry.
void expectTheTablesAnswers(const IsovalueMask& mask, const DiamondBounds& table, double asked,
                            const std::string& where) {
  std::size_t holding = 0, points = 0;
  for (const GridPoint& p : test_support::gridPoints(table.grid)) {
    const std::uint64_t i = table.grid.linearIndex(p);
    const bool expected = table.min[i] <= asked && asked <= table.max[i];
    ASSERT_EQ(mask.mayContain(p, asked), expected) << where << ", point " << p[0] << " " << p[1] << " " << p[2];
    EXPECT_EQ(mask.errorOf(p), table.error[i]) << where;
    holding += expected;
    ++points;
  }
  EXPECT_EQ(points, table.min.size());
  if (asked >= 30.0 && asked <= 220.0) {
    EXPECT_GT(holding, 0u) << where;  // these isovalues cut the random field: both answers occur
    EXPECT_LT(holding, points) << where;
  }
}

TEST(IsovalueMask, AnswersAsTheTableForItsIsovalueAndForOthers) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> value(0, 255);
  // 7 x 6 x 5 samples: a grid of 9^3 = 729 points, not a whole number of 64-bit words.
  const Volume<std::uint16_t> v = test_support::volumeOf({7, 6, 5}, [&](int, int, int) { return value(rng); });
  const DenseGridField field = test_support::denseField(v);
  const DiamondBounds table = computeDiamondBounds(field.grid(), field.values(), 1);
  ASSERT_EQ(table.min.size(), 729u);
  IsovalueMask mask(table, 100.0);
  EXPECT_EQ(mask.isovalue(), 100.0);
  // Its isovalue, then others through the table; the range's ends are where min or max equal it.
  for (const double asked : {100.0, 99.5, 255.0, 0.0, -1.0, 300.0})
    expectTheTablesAnswers(mask, table, asked, "mask of 100, asked " + std::to_string(asked));
  for (const double iso : {0.0, 37.5, 128.0, 255.0}) {
    mask.setIsovalue(iso);
    expectTheTablesAnswers(mask, table, iso, "mask of " + std::to_string(iso));
    expectTheTablesAnswers(mask, table, 100.0, "mask of " + std::to_string(iso) + ", asked 100");
  }
  // A NaN isovalue holds nowhere, made into bits or not.
  mask.setIsovalue(std::numeric_limits<double>::quiet_NaN());
  for (const GridPoint& p : test_support::gridPoints(table.grid))
    ASSERT_FALSE(mask.mayContain(p, std::numeric_limits<double>::quiet_NaN()));
}

TEST(IsovalueMask, KeepsTheTablesGrid) {
  const Volume<std::uint16_t> v =
      test_support::volumeOf({3, 3, 3}, [](int x, int y, int z) { return 10 * (x + y + z); });
  const DenseGridField field = test_support::denseField(v);
  const DiamondBounds table = computeDiamondBounds(field.grid(), field.values(), 1);
  const IsovalueMask mask(table, 30.0);
  EXPECT_EQ(mask.lebGrid().k, table.grid.k);
  expectTheTablesAnswers(mask, table, 30.0, "a 3^3 volume");
}

}  // namespace
}  // namespace voxref::ref
