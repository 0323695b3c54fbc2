#include <iostream>
#include <memory>

#include "conformance/cli/case_selection.h"
#include "conformance/cli/commands.h"
#include "conformance/framework/exit_status.h"
#include "conformance/framework/expectations/expectation_files.h"
#include "conformance/framework/run_selection.h"
#include "conformance/modules/catalog.h"

namespace voxref::cli {
namespace {

struct ListOptions {
  std::string filter = "*";
  std::string shard;  // "I/N" or empty
  bool runnerControls = false;
  std::vector<std::filesystem::path> caseLists, skips;
  int fraction = 1;
};

// The cases `voxref conform` with the same selection options runs (conformance/framework/run_selection.h).
int runList(const ListOptions& o) {
  conf::SelectionRequest request;
  request.filter = o.filter;
  std::string from;
  request.shard = shardOptionOrCi(o.shard, from);
  request.fraction = o.fraction;
  if (o.fraction < 1) throw conf::UsageError("--fraction must be at least 1");
  conf::Expectations skips;
  try {
    request.caseList = conf::readCaseLists(o.caseLists);
    skips = conf::readExpectations({}, {}, o.skips);
  } catch (const conf::ExpectationFileError& e) {
    throw conf::UsageError(e.what());
  }
  request.skips = &skips.skips;
  const auto cases = conf::selectRun(catalogue(o.runnerControls), request).cases;
  std::size_t width = 0;
  for (const auto& c : cases) width = std::max(width, c.id.size());
  for (const auto& c : cases) std::cout << c.id << std::string(width + 2 - c.id.size(), ' ') << c.description << "\n";
  return 0;
}

}  // namespace

Subcommand addListCommand(CLI::App& app) {
  auto o = std::make_shared<ListOptions>();
  CLI::App* sub = app.add_subcommand("list", "every case id with one line on what it checks");
  sub->add_option("--filter", o->filter, "shell-style glob on case ids")->default_val("*");
  sub->add_option("--shard", o->shard, "I/N: only the cases shard I of N runs (as conform --shard)");
  sub->add_flag("--runner-controls", o->runnerControls,
                "also the runner's control cases (deliberate crash, abort, hang)");
  sub->add_option("--caselist", o->caseLists, "a file of case ids, one per line (as conform --caselist); repeatable");
  sub->add_option("--skips", o->skips, "regular expressions of cases left out (as conform --skips); repeatable");
  sub->add_option("--fraction", o->fraction, "every Nth case (as conform --fraction)")->default_val(1);

  return {sub, [o] { return runList(*o); }};
}

}  // namespace voxref::cli
