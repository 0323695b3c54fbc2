// libFuzzer target: reading a results.json back (conformance/framework/report/results_reader.h): the
// baseline of `voxref conform --baseline OLD/results.json`, and (caseFromJson) the result a
// case's process hands to the runner. Then what --baseline does with it: the diff against
// another run (conformance/framework/report/baseline_diff.h), its JSON and its terminal report.
//
// Contract under test:
// - parseResults (the bytes of a file; loadResults reads the file and calls it) either returns or
//   throws ResultsFormatError; caseFromJson, on any JSON value, either returns or throws
//   ResultsFormatError; nothing else escapes (no nlohmann::json exception either), nothing reads
//   out of bounds (ASan), no undefined behaviour (UBSan: a NaN or 1e300 converted into an int is
//   one);
// - the cases read are safe to compare: compareWithBaseline, baselineJson (and its dump) and
//   printBaselineDiff run on them (against themselves, against nothing, and against a run whose
//   every case took the next case's status and oracles) without an exception.
// Size cap: none; inputs are as long as libFuzzer's -max_len.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string_view>
#include <vector>

#include "conformance/framework/report/baseline_diff.h"
#include "conformance/framework/report/results_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace voxref::conf;
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  // caseFromJson on every value the document holds at the top and in "cases".
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(bytes);
  } catch (const nlohmann::json::exception&) {
  }
  auto tryCase = [](const nlohmann::json& v) {
    try {
      (void)caseFromJson(v);
    } catch (const ResultsFormatError&) {
    }
  };
  tryCase(j);
  if (j.is_object())
    if (const auto it = j.find("cases"); it != j.end() && it->is_array())
      for (const auto& c : *it) tryCase(c);

  LoadedResults r;
  try {
    r = parseResults(bytes, "results.json");
  } catch (const ResultsFormatError&) {
    return 0;
  }
  std::vector<CaseResult> shifted = r.cases;
  for (std::size_t i = 0; i + 1 < shifted.size(); ++i) {
    shifted[i].status = r.cases[i + 1].status;
    shifted[i].oracles = r.cases[i + 1].oracles;
  }
  std::ostringstream out;
  for (const BaselineDiff& d : {compareWithBaseline(r.cases, r.cases), compareWithBaseline(r.cases, {}),
                                compareWithBaseline({}, r.cases), compareWithBaseline(r.cases, shifted)}) {
    (void)baselineJson(d, "results.json").dump();
    printBaselineDiff(out, d, "results.json");
  }
  return 0;
}
