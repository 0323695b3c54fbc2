// The files a CI job commits beside its driver, in deqp-runner's formats (docs/ci.md): a fails
// file (`case.id,Status` per line), flakes and skips files (one regular expression per line) and
// case lists (one case id per line). In every file a line that is empty or starts with '#' (after
// leading blanks) is ignored, and a '\r' before the newline is dropped.
//
// Each reader reads one whole file and throws ExpectationFileError naming the file, the line and
// what was expected there; nothing is half-read.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "conformance/framework/case.h"

namespace voxref::conf {

class ExpectationFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Where an entry came from, for messages: "fails.txt:12".
struct FileLine {
  std::string file;
  int line = 0;
};

struct ExpectedStatus {
  Status status = Status::Fail;  // Fail, Crash, Timeout or Warn
  FileLine from;
};

struct Pattern {
  std::string text;  // as written
  std::regex regex;  // ECMAScript; matches anywhere in the id (std::regex_search), as deqp-runner's
  FileLine from;
};

// What the expectation files of a run say, all files of a kind together.
struct Expectations {
  std::map<std::string, ExpectedStatus> fails;  // by case id
  std::vector<Pattern> flakes, skips;
  bool empty() const { return fails.empty() && flakes.empty() && skips.empty(); }
};

// Parsers of one file's text; `file` names it in errors. A fails line is `id,Status` with Status
// one of Fail, Crash, Timeout, Warn (deqp-runner's spelling); an id given twice, in one file or in
// two, is an error. A pattern that std::regex cannot compile is an error.
void parseFailsText(const std::string& text, const std::string& file, std::map<std::string, ExpectedStatus>& into);
// A pattern is at most kMaxPatternLength characters.
inline constexpr std::size_t kMaxPatternLength = 500;
std::vector<Pattern> parsePatternsText(const std::string& text, const std::string& file);
struct ListedCase {
  std::string id;
  FileLine from;
};
// A case list: ids of the form a.b_c (lower-case letters, digits, '_', '.'), each once.
std::vector<ListedCase> parseCaseListText(const std::string& text, const std::string& file);

// Reads the files (each option repeatable). Throws ExpectationFileError for a file that is missing
// or unreadable, or for a bad line.
Expectations readExpectations(const std::vector<std::filesystem::path>& fails,
                              const std::vector<std::filesystem::path>& flakes,
                              const std::vector<std::filesystem::path>& skips);
// The ids of every case list, in the order of the files; an id in two lists is an error.
std::vector<ListedCase> readCaseLists(const std::vector<std::filesystem::path>& lists);

// The first pattern that matches `id`, or nullptr.
const Pattern* firstMatch(const std::vector<Pattern>& patterns, const std::string& id);

}  // namespace voxref::conf
