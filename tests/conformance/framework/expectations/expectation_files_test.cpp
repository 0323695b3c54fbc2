#include "conformance/framework/expectations/expectation_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/scratch_folder.h"

namespace voxref::conf {
namespace {

// The message of the ExpectationFileError `f` throws ("" when it throws none).
template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const ExpectationFileError& e) {
    return e.what();
  }
  return "";
}

TEST(FailsFile, ReadsDeqpRunnerLinesWithCommentsBlanksAndCrLf) {
  std::map<std::string, ExpectedStatus> fails;
  parseFailsText("# softpipe\n\nsparsegrid.a.b,Fail\r\n  iso.c,Crash  \ntimevarying.d,Timeout\nx.y,Warn\n", "f.txt",
                 fails);
  ASSERT_EQ(fails.size(), 4u);
  EXPECT_EQ(fails.at("sparsegrid.a.b").status, Status::Fail);
  EXPECT_EQ(fails.at("sparsegrid.a.b").from.line, 3);
  EXPECT_EQ(fails.at("iso.c").status, Status::Crash);
  EXPECT_EQ(fails.at("timevarying.d").status, Status::Timeout);
  EXPECT_EQ(fails.at("x.y").status, Status::Warn);
}

TEST(FailsFile, NamesTheFileTheLineAndWhatWasExpected) {
  std::map<std::string, ExpectedStatus> fails;
  EXPECT_EQ(errorOf([&] { parseFailsText("a.b,Fail\na.c,Broken\n", "fails.txt", fails); }),
            "fails.txt:2: unknown status 'Broken' (expected Fail, Crash, Timeout or Warn)");
  fails.clear();
  EXPECT_EQ(errorOf([&] { parseFailsText("a.b Fail\n", "fails.txt", fails); }),
            "fails.txt:1: expected 'case.id,Status' (Status: Fail, Crash, Timeout or Warn), got 'a.b Fail'");
  fails.clear();
  EXPECT_EQ(errorOf([&] { parseFailsText("# c\nA.B,Fail\n", "fails.txt", fails); }),
            "fails.txt:2: 'A.B' is not a case id (lower-case letters, digits, '_' and '.')");
  fails.clear();
  EXPECT_EQ(errorOf([&] { parseFailsText("a.b,Fail\na.b,Crash\n", "fails.txt", fails); }),
            "fails.txt:2: a.b is already expected at fails.txt:1");
  fails.clear();
  // Pass and Skip are not expectations: a pass needs no entry, a skip is never a failure.
  EXPECT_NE(errorOf([&] { parseFailsText("a.b,Pass\n", "f", fails); }), "");
  EXPECT_NE(errorOf([&] { parseFailsText("a.b,fail\n", "f", fails); }), "") << "deqp-runner's spelling only";
}

TEST(PatternsFile, MatchesAnywhereInTheIdAndRejectsABadExpression) {
  const auto p =
      parsePatternsText("# flaky on softpipe\nsparsegrid\\.texture\\..*repeat\n^iso\\.frames\n", "flakes.txt");
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(firstMatch(p, "sparsegrid.texture.r8.exact.nearest.repeat"), &p[0]);
  EXPECT_EQ(firstMatch(p, "x.sparsegrid.texture.a.repeat"), &p[0]) << "a search, not an anchored match";
  EXPECT_EQ(firstMatch(p, "iso.frames.buckyball"), &p[1]);
  EXPECT_EQ(firstMatch(p, "prefix.iso.frames.buckyball"), nullptr);
  // What libstdc++'s regex compiler overflows on is refused before it sees it.
  EXPECT_EQ(errorOf([] { parsePatternsText("(a)\\1\n", "f.txt"); }),
            "f.txt:1: '(a)\\1': back-references (\\1 ...) are not supported");
  EXPECT_EQ(errorOf([] { parsePatternsText("x{1,99999}\n", "f.txt"); }),
            "f.txt:1: 'x{1,99999}': a repetition count of more than four digits");
  EXPECT_EQ(parsePatternsText("x{1,9999}\\.\\0\n", "f.txt").size(), 1u);
  const std::string e = errorOf([] { parsePatternsText("ok\n(unclosed\n", "skips.txt"); });
  EXPECT_EQ(e.rfind("skips.txt:2: '(unclosed' is not a regular expression", 0), 0u) << e;
}

TEST(CaseList, ReadsIdsAndRefusesDuplicatesAcrossFiles) {
  const test::ScratchFolder dir;
  std::ofstream(dir / "a.txt") << "# first\nsparsegrid.hard.level1\niso.hard.single_voxel\n";
  std::ofstream(dir / "b.txt") << "timevarying.hard.flag_collision.paper\nsparsegrid.hard.level1\n";
  const auto one = readCaseLists({dir / "a.txt"});
  ASSERT_EQ(one.size(), 2u);
  EXPECT_EQ(one[1].id, "iso.hard.single_voxel");
  EXPECT_EQ(one[1].from.line, 3);
  EXPECT_EQ(
      errorOf([&] {
        readCaseLists({dir / "a.txt", dir / "b.txt"});
      }),
      (dir / "b.txt").string() + ":2: sparsegrid.hard.level1 is already listed at " + (dir / "a.txt").string() + ":2");
  EXPECT_EQ(errorOf([&] { readCaseLists({dir / "missing.txt"}); }),
            "case list " + (dir / "missing.txt").string() + " does not exist");
  EXPECT_EQ(errorOf([&] { readExpectations({dir.path()}, {}, {}); }),
            "fails file " + dir.path().string() + " is not a regular file");
}

}  // namespace
}  // namespace voxref::conf
