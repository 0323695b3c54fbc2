#include <iostream>
#include <memory>

#include "conformance/cli/case_selection.h"
#include "conformance/cli/commands.h"
#include "conformance/framework/exit_status.h"
#include "conformance/framework/selection.h"
#include "conformance/modules/catalog.h"

namespace voxref::cli {
namespace {

struct ListOptions {
  std::string filter = "*";
  std::string shard;  // "I/N" or empty
  bool runnerControls = false;
};

int runList(const ListOptions& o) {
  auto cases = conf::selectCases(catalogue(o.runnerControls), o.filter);
  if (cases.empty()) throw conf::UsageError("no case matches '" + o.filter + "'");
  if (const auto shard = shardOption(o.shard)) cases = conf::shardOf(cases, *shard);
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

  return {sub, [o] { return runList(*o); }};
}

}  // namespace voxref::cli
