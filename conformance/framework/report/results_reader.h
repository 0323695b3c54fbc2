// Reading results.json back (results_json.h writes it): how a case's result crosses from its
// process to the runner (isolation/child_processes.h), and how `--baseline` reads an old run.
// Safe on untrusted input: a file that is not a voxref results file gives ResultsFormatError
// naming the field and what was expected, never a crash.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "conformance/framework/case.h"

namespace voxref::conf {

class ResultsFormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The inverse of caseJson(): caseJson(caseFromJson(j)) == j for every j caseJson wrote.
CaseResult caseFromJson(const nlohmann::json& j);

// A results.json file: its cases and the whole document (for the driver block and counts).
struct LoadedResults {
  nlohmann::json document;
  std::vector<CaseResult> cases;
};
// Throws ResultsFormatError for a missing or unreadable file, bad JSON, or a document whose
// "format" is not "voxref-results" version 1.
LoadedResults loadResults(const std::filesystem::path& file);
// The same from the file's bytes (loadResults reads the file and calls this); `sourceName` names
// the file in the errors. Throws ResultsFormatError only.
LoadedResults parseResults(std::string_view bytes, const std::string& sourceName);

}  // namespace voxref::conf
