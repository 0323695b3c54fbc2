// Checks a results.json written by `voxref conform` against what a test expects of the run.
//   check_results FILE [--profile NAME] [--require-exact-pass] [--require-no-fail]
//                      [--require-explained-envelope] [--expect-finding ID]... [--min-cases N]
// --require-exact-pass: every case whose exact oracle ran passed it with 0 mismatched samples.
// --require-explained-envelope: every envelope failure or warning lies at a sample that a named
//   departure of the driver's profile changes (figures unexplained_failures/warnings are 0).
// --expect-finding ID: the finding changes samples in at least one case.
// Prints every violation; exits 1 if there is any, 2 on bad usage or an unreadable file.
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: check_results results.json [options]\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::cerr << "check_results: cannot read " << argv[1] << "\n";
    return 2;
  }
  nlohmann::json r;
  try {
    r = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    std::cerr << "check_results: " << argv[1] << " is not JSON: " << e.what() << "\n";
    return 2;
  }
  std::string profile;
  bool exactPass = false, noFail = false, explained = false;
  std::vector<std::string> findings;
  std::size_t minCases = 1;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--profile" && i + 1 < argc) profile = argv[++i];
    else if (a == "--require-exact-pass") exactPass = true;
    else if (a == "--require-no-fail") noFail = true;
    else if (a == "--require-explained-envelope") explained = true;
    else if (a == "--expect-finding" && i + 1 < argc) findings.push_back(argv[++i]);
    else if (a == "--min-cases" && i + 1 < argc) minCases = std::stoul(argv[++i]);
    else {
      std::cerr << "check_results: unknown option " << a << "\n";
      return 2;
    }
  }
  int violations = 0;
  auto violation = [&](const std::string& what) {
    ++violations;
    std::cout << "VIOLATION: " << what << "\n";
  };
  if (!r.value("complete", false)) violation("the run is marked incomplete");
  const auto& cases = r["cases"];
  if (cases.size() < minCases) violation("only " + std::to_string(cases.size()) + " cases ran");
  if (!profile.empty() && r["driver"]["profile"]["name"] != profile)
    violation("profile is " + r["driver"]["profile"]["name"].dump() + ", expected " + profile);
  std::size_t exactRan = 0;
  for (const auto& c : cases) {
    const std::string id = c["id"];
    const std::string status = c["status"];
    if (noFail && (status == "fail" || status == "crash" || status == "timeout")) violation(id + " is " + status + ": " + c["message"].get<std::string>());
    if (status == "crash") violation(id + " crashed: " + c["message"].get<std::string>());
    const auto& oracles = c["oracles"];
    if (exactPass && oracles.contains("exact") && oracles["exact"]["verdict"] != "not_run") {
      ++exactRan;
      const auto& e = oracles["exact"];
      const auto& f = e["figures"];
      if (e["verdict"] != "pass" || f.value("mismatched_samples", 1) != 0 || f.value("mismatched_pixels", 1) != 0)
        violation(id + ": exact oracle " + e["verdict"].get<std::string>() + ": " + e["summary"].get<std::string>());
    }
    if (explained && oracles.contains("envelope")) {
      const auto& f = oracles["envelope"]["figures"];
      if (f.value("unexplained_failures", 0) != 0 || f.value("unexplained_warnings", 0) != 0 ||
          (!f.contains("unexplained_failures") && (f.value("fail", 0) != 0 || f.value("quality_warning", 0) != 0)))
        violation(id + ": envelope failures not explained by a named departure: " + oracles["envelope"]["summary"].get<std::string>());
    }
  }
  if (exactPass && exactRan == 0) violation("no case ran the exact oracle");
  for (const std::string& want : findings) {
    bool seen = false;
    for (const auto& c : cases)
      for (const auto& f : c["findings"])
        if (f["id"] == want && f["figures"].value("samples_changed", 0) > 0) seen = true;
    if (!seen) violation("finding " + want + " changed no sample in any case");
  }
  std::cout << "check_results: " << cases.size() << " cases, " << exactRan << " with the exact oracle, " << violations << " violation(s)\n";
  return violations ? 1 : 0;
}
