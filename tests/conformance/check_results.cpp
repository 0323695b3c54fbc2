// Checks a results.json written by `voxref conform` against what a test expects of the run.
//   check_results FILE [--profile NAME] [--require-exact-pass] [--require-no-fail]
//                      [--require-explained-envelope] [--expect-finding ID]... [--min-cases N]
// --require-exact-pass: every case whose exact oracle ran passed it with 0 mismatched samples.
// --require-explained-envelope: every envelope failure or warning lies at a sample that a named
//   departure of the driver's profile changes (figures unexplained_failures/warnings are 0).
// --expect-finding ID: the finding changes samples in at least one case.
// --expect-status ID=STATUS: the case ran and has that status (crash, timeout, ...); the
//   incomplete-run and crash checks then apply to the other cases only.
// --expect-stderr ID=TEXT: the case's kept stdout/stderr contains TEXT.
// --expect-oracle ID:ORACLE=VERDICT: the case ran and its oracle ORACLE gave that verdict (pass,
//   fail, not_run, ...): an oracle that must have judged, or must have said why it could not.
// --expect-interrupted: the run is marked incomplete, names its signal, lists the cases not run,
//   and every listed case ran to a status.
// --same-results-as OTHER.json: every case has the same status, message, oracles, effects,
//   findings, figures and worst pixels as in OTHER (times, stderr and the run's own fields such
//   as the command and --jobs aside), and every image file both name is the same, byte for byte.
//   Cases are matched by id; both runs hold the same cases.
// --same-results-as-subset OTHER.json: the same, where OTHER may hold more cases than this run.
// --expect-envelope-alone: the run names no profile and says it is judged by the envelope alone;
//   no case ran the exact oracle, and every case's envelope oracle ran.
// --expect-regressed ID / --expect-fixed ID: the "baseline" block lists the case so.
// --require-failures-with-finding ID: every failed case carries the finding ID, and it changed
//   samples there (a driver defect named as the reason of each failure).
// --expect-environment NAME=VALUE: the run records the variable (driver.environment), and the
//   index.html beside it shows it.
// Always: every case that is not a pass states its reason (a non-empty message), and the
// junit.xml beside the results has no failure or skip without a message.
// Prints every violation; exits 1 if there is any, 2 on bad usage or an unreadable file.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace {

bool readJson(const std::string& file, nlohmann::json& out) {
  std::ifstream in(file);
  if (!in) {
    std::cerr << "check_results: cannot read " << file << "\n";
    return false;
  }
  try {
    out = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    std::cerr << "check_results: " << file << " is not JSON: " << e.what() << "\n";
    return false;
  }
  return true;
}

std::string fileBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return in ? s.str() : std::string("\x01missing");
}

// A case without what may differ between equal runs.
nlohmann::json stable(nlohmann::json c) {
  for (const char* k : {"seconds_gl", "seconds_emulation", "seconds_reference", "seconds", "timings", "stderr"})
    c.erase(k);
  return c;
}

std::pair<std::string, std::string> splitAt(const std::string& s) {
  const auto eq = s.find('=');
  return {s.substr(0, eq), eq == std::string::npos ? std::string() : s.substr(eq + 1)};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: check_results results.json [options]\n";
    return 2;
  }
  nlohmann::json r;
  if (!readJson(argv[1], r)) return 2;
  std::string profile;
  bool exactPass = false, noFail = false, explained = false;
  std::vector<std::string> findings;
  std::size_t minCases = 1;
  std::map<std::string, std::string> expectStatus, expectStderr, expectEnvironment, expectOracle;
  std::vector<std::string> expectRegressed, expectFixed, failuresWithFinding;
  bool expectInterrupted = false, envelopeAlone = false;
  std::string sameAs;
  bool sameAsSubset = false;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--profile" && i + 1 < argc)
      profile = argv[++i];
    else if (a == "--require-exact-pass")
      exactPass = true;
    else if (a == "--require-no-fail")
      noFail = true;
    else if (a == "--require-explained-envelope")
      explained = true;
    else if (a == "--expect-finding" && i + 1 < argc)
      findings.push_back(argv[++i]);
    else if (a == "--min-cases" && i + 1 < argc)
      minCases = std::stoul(argv[++i]);
    else if (a == "--expect-status" && i + 1 < argc)
      expectStatus.insert(splitAt(argv[++i]));
    else if (a == "--expect-stderr" && i + 1 < argc)
      expectStderr.insert(splitAt(argv[++i]));
    else if (a == "--expect-oracle" && i + 1 < argc)
      expectOracle.insert(splitAt(argv[++i]));
    else if (a == "--expect-interrupted")
      expectInterrupted = true;
    else if (a == "--expect-envelope-alone")
      envelopeAlone = true;
    else if (a == "--same-results-as" && i + 1 < argc)
      sameAs = argv[++i];
    else if (a == "--same-results-as-subset" && i + 1 < argc) {
      sameAs = argv[++i];
      sameAsSubset = true;
    } else if (a == "--expect-regressed" && i + 1 < argc)
      expectRegressed.push_back(argv[++i]);
    else if (a == "--expect-fixed" && i + 1 < argc)
      expectFixed.push_back(argv[++i]);
    else if (a == "--require-failures-with-finding" && i + 1 < argc)
      failuresWithFinding.push_back(argv[++i]);
    else if (a == "--expect-environment" && i + 1 < argc)
      expectEnvironment.insert(splitAt(argv[++i]));
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
  if (expectInterrupted) {
    if (r.value("complete", true)) violation("the run is not marked incomplete");
    if (!r["interrupted_by"].is_string()) violation("the run does not name the signal that interrupted it");
    if (r["not_run"].empty()) violation("the interrupted run lists no case as not run");
  } else if (!r.value("complete", false)) {
    violation("the run is marked incomplete");
  }
  const auto& cases = r["cases"];
  if (cases.size() < minCases) violation("only " + std::to_string(cases.size()) + " cases ran");
  if (!profile.empty() && r["driver"]["profile"]["name"] != profile)
    violation("profile is " + r["driver"]["profile"]["name"].dump() + ", expected " + profile);
  std::size_t exactRan = 0;
  for (const auto& c : cases) {
    const std::string id = c["id"];
    const std::string status = c["status"];
    if (noFail && (status == "fail" || status == "crash" || status == "timeout"))
      violation(id + " is " + status + ": " + c["message"].get<std::string>());
    for (auto want = expectOracle.begin(); want != expectOracle.end();) {
      const std::size_t colon = want->first.find(':');
      if (want->first.substr(0, colon) != id) {
        ++want;
        continue;
      }
      const std::string oracle = colon == std::string::npos ? "" : want->first.substr(colon + 1);
      const auto& oracles = c["oracles"];
      if (!oracles.contains(oracle))
        violation(id + " has no oracle '" + oracle + "'");
      else if (oracles[oracle]["verdict"] != want->second)
        violation(id + ": oracle " + oracle + " is " + oracles[oracle]["verdict"].dump() + ", expected " +
                  want->second + ": " + oracles[oracle]["summary"].get<std::string>());
      want = expectOracle.erase(want);
    }
    if (const auto want = expectStatus.find(id); want != expectStatus.end()) {
      if (status != want->second)
        violation(id + " is " + status + ", expected " + want->second + ": " + c["message"].get<std::string>());
      expectStatus.erase(want);
      if (const auto text = expectStderr.find(id); text != expectStderr.end()) {
        if (c.value("stderr", "").find(text->second) == std::string::npos)
          violation(id + ": stderr kept does not contain '" + text->second +
                    "': " + c.value("stderr", "").substr(0, 300));
        expectStderr.erase(text);
      }
      continue;
    }
    if (status != "pass" && c.value("message", "").empty())
      violation(id + " is " + status + " and states no reason (empty message)");
    for (const std::string& want : failuresWithFinding) {
      if (status != "fail") continue;
      bool carried = false;
      for (const auto& f : c["findings"]) carried |= f["id"] == want && f["figures"].value("samples_changed", 0) > 0;
      if (!carried) violation(id + " fails without the finding " + want + ": " + c.value("message", ""));
    }
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
        violation(id + ": envelope failures not explained by a named departure: " +
                  oracles["envelope"]["summary"].get<std::string>());
    }
  }
  if (exactPass && exactRan == 0) violation("no case ran the exact oracle");
  for (const auto& [key, value] : expectEnvironment) {
    const auto& env = r["driver"]["environment"];
    if (!env.contains(key) || env[key] != value)
      violation("driver.environment does not record " + key + "=" + value + ": " + env.dump());
    const std::string index = fileBytes(std::filesystem::path(argv[1]).parent_path() / "index.html");
    if (index.find(key) == std::string::npos || index.find(value) == std::string::npos)
      violation("index.html does not show " + key + "=" + value);
  }
  if (const std::filesystem::path junit = std::filesystem::path(argv[1]).parent_path() / "junit.xml";
      std::filesystem::exists(junit)) {
    const std::string xml = fileBytes(junit);
    if (xml.find("message=\"\"") != std::string::npos)
      violation("junit.xml has message=\"\": a case without its reason");
  }
  for (const std::string& want : findings) {
    bool seen = false;
    for (const auto& c : cases)
      for (const auto& f : c["findings"])
        if (f["id"] == want && f["figures"].value("samples_changed", 0) > 0) seen = true;
    if (!seen) violation("finding " + want + " changed no sample in any case");
  }
  if (envelopeAlone) {
    const auto& p = r["driver"]["profile"];
    if (!p["name"].is_null()) violation("the run names profile " + p["name"].dump());
    if (p.value("chosen", "").find("envelope oracle alone") == std::string::npos)
      violation("the run does not say it is judged by the envelope alone");
    for (const auto& c : cases) {
      const auto& o = c["oracles"];
      if (o.contains("exact") && o["exact"]["verdict"] != "not_run")
        violation(c["id"].get<std::string>() + ": the exact oracle ran without a profile");
      if (!o.contains("envelope") || o["envelope"]["verdict"] == "not_run")
        violation(c["id"].get<std::string>() + ": the envelope oracle did not run");
    }
  }
  for (const auto& [id, status] : expectStatus) violation(id + " did not run (expected " + status + ")");
  for (const auto& [id, verdict] : expectOracle) violation(id + " did not run (expected its oracle " + verdict + ")");
  for (const auto& [id, text] : expectStderr)
    violation(id + ": --expect-stderr needs --expect-status for the same case");
  auto listed = [&](const char* list, const std::string& id) {
    if (!r["baseline"].is_object()) return false;
    for (const auto& c : r["baseline"][list])
      if (c["id"] == id) return true;
    return false;
  };
  for (const std::string& id : expectRegressed)
    if (!listed("newly_failing", id) && !listed("newly_warning", id))
      violation(id + " is not listed as regressed against the baseline");
  for (const std::string& id : expectFixed)
    if (!listed("fixed", id)) violation(id + " is not listed as fixed against the baseline");
  if (!sameAs.empty()) {
    nlohmann::json other;
    if (!readJson(sameAs, other)) return 2;
    // Cases are matched by id. Every case of this run must be in OTHER with the same results; with
    // --same-results-as-subset OTHER may hold more (a smaller run checked against a larger one).
    std::map<std::string, const nlohmann::json*> otherById;
    for (const auto& c : other["cases"]) otherById[c.value("id", "")] = &c;
    if (!sameAsSubset && other["cases"].size() != cases.size())
      violation("the runs hold " + std::to_string(cases.size()) + " and " + std::to_string(other["cases"].size()) +
                " cases");
    const std::filesystem::path here = std::filesystem::path(argv[1]).parent_path(),
                                there = std::filesystem::path(sameAs).parent_path();
    std::size_t images = 0;
    for (const auto& c : cases) {
      const std::string id = c.value("id", "");
      const auto found = otherById.find(id);
      if (found == otherById.end()) {
        violation(id + " is not in " + sameAs);
        continue;
      }
      const nlohmann::json a = stable(c), b = stable(*found->second);
      if (a != b) {
        violation(id + " differs from " + id + " in " + sameAs);
        continue;
      }
      for (const auto& [kind, file] : a["images"].items()) {
        ++images;
        if (fileBytes(here / file.get<std::string>()) != fileBytes(there / file.get<std::string>()))
          violation(id + ": image " + file.get<std::string>() + " differs between the runs");
      }
    }
    std::cout << "check_results: compared with " << sameAs << ": " << images
              << " image file(s) compared byte for byte\n";
  }
  std::cout << "check_results: " << cases.size() << " cases, " << exactRan << " with the exact oracle, " << violations
            << " violation(s)\n";
  return violations ? 1 : 0;
}
