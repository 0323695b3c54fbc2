// `voxref suite FILE.toml`: the configurations of a suite file (conformance/framework/suite/
// suite_file.h), each run as its own `voxref conform` process with its environment, its report in
// OUT/<name>/; then OUT/results.csv and OUT/failures.csv, the entries' files together (ids carry
// each entry's prefix), and one exit status (docs/ci.md, "Suite files").
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "conformance/cli/commands.h"
#include "conformance/framework/exit_status.h"
#include "conformance/framework/suite/suite_file.h"
#include "conformance/io/atomic_file.h"

extern char** environ;

namespace voxref::cli {
namespace {

struct SuiteOptions {
  std::filesystem::path file;
  std::filesystem::path out = "voxref-suite";
  int jobs = 1;
};

std::vector<std::string> conformArguments(const conf::SuiteEntry& e, const SuiteOptions& o) {
  std::vector<std::string> a{"voxref",         "conform",
                             "--driver",       e.driver,
                             "--profile",      e.profile,
                             "--filter",       e.filter,
                             "--prefix",       e.prefix,
                             "--fraction",     std::to_string(e.fraction),
                             "--flake-reruns", std::to_string(e.flakeReruns),
                             "--jobs",         std::to_string(o.jobs),
                             "--out",          (o.out / e.name).string()};
  auto each = [&](const char* option, const std::vector<std::filesystem::path>& files) {
    for (const auto& f : files) a.insert(a.end(), {option, f.string()});
  };
  each("--caselist", e.caseLists);
  each("--fails", e.fails);
  each("--flakes", e.flakes);
  each("--skips", e.skips);
  if (!e.rendererCheck.empty()) a.insert(a.end(), {"--renderer-check", e.rendererCheck});
  if (!e.versionCheck.empty()) a.insert(a.end(), {"--version-check", e.versionCheck});
  return a;
}

// This process's environment with the entry's variables set over it.
std::vector<std::string> environmentOf(const conf::SuiteEntry& e) {
  std::map<std::string, std::string> env;
  for (char** p = environ; *p; ++p) {
    const std::string kv(*p);
    const auto eq = kv.find('=');
    if (eq != std::string::npos) env[kv.substr(0, eq)] = kv.substr(eq + 1);
  }
  for (const auto& [k, v] : e.env) env[k] = v;
  std::vector<std::string> out;
  for (const auto& [k, v] : env) out.push_back(k + "=" + v);
  return out;
}

// Runs `voxref conform` for the entry and returns its exit status (128 + signal when killed).
int runEntry(const conf::SuiteEntry& e, const SuiteOptions& o) {
  std::vector<std::string> args = conformArguments(e, o), env = environmentOf(e);
  std::vector<char*> argv, envp;
  for (std::string& s : args) argv.push_back(s.data());
  argv.push_back(nullptr);
  for (std::string& s : env) envp.push_back(s.data());
  envp.push_back(nullptr);
  pid_t pid = 0;
  if (const int err = posix_spawn(&pid, "/proc/self/exe", nullptr, nullptr, argv.data(), envp.data()))
    throw std::runtime_error("cannot start voxref conform for suite entry '" + e.name + "': " + std::strerror(err));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("waiting for suite entry '" + e.name + "' failed");
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string readIfThere(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int runSuite(const SuiteOptions& o) {
  std::vector<conf::SuiteEntry> entries;
  try {
    entries = conf::readSuiteFile(o.file);
  } catch (const conf::SuiteFileError& e) {
    throw conf::UsageError(e.what());
  }
  if (o.jobs < 1) throw conf::UsageError("--jobs must be at least 1");
  io::ensureDirectory(o.out);
  std::string results, failures;
  std::vector<std::pair<std::string, int>> exits;
  for (const conf::SuiteEntry& e : entries) {
    std::cout << "suite " << o.file.filename().string() << ": entry " << e.name << " (" << e.driver
              << (e.env.empty() ? "" : ", its environment") << ")" << std::endl;
    const int status = runEntry(e, o);
    exits.emplace_back(e.name, status);
    results += readIfThere(o.out / e.name / "results.csv");
    failures += readIfThere(o.out / e.name / "failures.csv");
    if (status >= 128) break;  // interrupted: the entries after it do not run
  }
  io::writeFileAtomically(o.out / "results.csv", results);
  io::writeFileAtomically(o.out / "failures.csv", failures);
  bool anyUsage = false, anyFailed = false;
  int interrupted = 0;
  std::cout << "suite:";
  for (const auto& [name, status] : exits) {
    std::cout << " " << name << " exit " << status << ";";
    anyUsage = anyUsage || status == conf::kExitUsage;
    anyFailed = anyFailed || status != 0;
    if (status >= 128) interrupted = status;
  }
  std::cout << " " << exits.size() << " of " << entries.size() << " entries ran\n"
            << "suite report: " << o.out.string() << "/<entry>/ and " << (o.out / "results.csv").string()
            << ", failures.csv\n";
  return interrupted ? interrupted : anyUsage ? conf::kExitUsage : anyFailed ? conf::kExitFailed : conf::kExitPass;
}

}  // namespace

Subcommand addSuiteCommand(CLI::App& app) {
  auto o = std::make_shared<SuiteOptions>();
  CLI::App* sub = app.add_subcommand("suite", "run the configurations of a suite file (TOML), each as voxref conform");
  sub->add_option("file", o->file, "the suite file (docs/ci.md, \"Suite files\")")->required();
  sub->add_option("--out", o->out, "report directory: one folder per entry, and the entries' CSV files together")
      ->default_val("voxref-suite");
  sub->add_option("--jobs,-j", o->jobs, "case processes at once in each entry's run")->default_val(1);
  return {sub, [o] { return runSuite(*o); }};
}

}  // namespace voxref::cli
