#include "conformance/framework/expectations/expectation_files.h"

#include <set>
#include <sstream>

#include "conformance/io/atomic_file.h"

namespace voxref::conf {
namespace {

std::string where(const std::string& file, int line) { return file + ":" + std::to_string(line); }

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

// Calls `each(content, lineNumber)` for every line that is not empty or a comment.
template <class Each>
void forEachEntry(const std::string& text, Each each) {
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    each(t, number);
  }
}

bool isCaseId(const std::string& s) {
  if (s.empty() || s.front() == '.' || s.back() == '.') return false;
  for (char c : s)
    if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.')) return false;
  return s.find("..") == std::string::npos;
}

// The file through io::readWholeFile, its error named by what the file is ("fails file ...").
std::string readWhole(const std::filesystem::path& path, const char* what) {
  try {
    return io::readWholeFile(path);
  } catch (const io::IoError& e) {
    throw ExpectationFileError(std::string(what) + " " + e.what());
  }
}

// What libstdc++'s std::regex must not see (its compiler multiplies digit runs into a long without
// a bound: a back-reference or repetition count of 19 digits is signed overflow, found by
// expectation_files_fuzz): back-references, which deqp-runner's regex syntax has none of either,
// and repetition counts of more than four digits. Returns the problem, or "".
std::string unsupportedSyntax(const std::string& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i] == '\\' && i + 1 < p.size()) {
      if (p[i + 1] >= '1' && p[i + 1] <= '9') return "back-references (\\1 ...) are not supported";
      ++i;
    } else if (p[i] == '{') {
      std::size_t digits = 0;
      for (std::size_t j = i + 1; j < p.size() && p[j] != '}'; ++j) {
        digits = (p[j] >= '0' && p[j] <= '9') ? digits + 1 : 0;
        if (digits > 4) return "a repetition count of more than four digits";
      }
    }
  }
  return "";
}

}  // namespace

void parseFailsText(const std::string& text, const std::string& file, std::map<std::string, ExpectedStatus>& into) {
  forEachEntry(text, [&](const std::string& entry, int line) {
    const auto comma = entry.find(',');
    if (comma == std::string::npos)
      throw ExpectationFileError(where(file, line) +
                                 ": expected 'case.id,Status' (Status: Fail, Crash, Timeout or Warn), got '" + entry +
                                 "'");
    const std::string id = trim(entry.substr(0, comma)), status = trim(entry.substr(comma + 1));
    if (!isCaseId(id))
      throw ExpectationFileError(where(file, line) + ": '" + id +
                                 "' is not a case id (lower-case letters, digits, '_' and '.')");
    std::optional<Status> s;
    if (status == "Fail") s = Status::Fail;
    if (status == "Crash") s = Status::Crash;
    if (status == "Timeout") s = Status::Timeout;
    if (status == "Warn") s = Status::Warn;
    if (!s)
      throw ExpectationFileError(where(file, line) + ": unknown status '" + status +
                                 "' (expected Fail, Crash, Timeout or Warn)");
    const auto [it, added] = into.emplace(id, ExpectedStatus{*s, {file, line}});
    if (!added)
      throw ExpectationFileError(where(file, line) + ": " + id + " is already expected at " +
                                 where(it->second.from.file, it->second.from.line));
  });
}

std::vector<Pattern> parsePatternsText(const std::string& text, const std::string& file) {
  std::vector<Pattern> out;
  forEachEntry(text, [&](const std::string& entry, int line) {
    // std::regex compiles and matches by recursion: a bound on the pattern bounds its depth.
    if (entry.size() > kMaxPatternLength)
      throw ExpectationFileError(where(file, line) + ": a pattern of " + std::to_string(entry.size()) +
                                 " characters; at most " + std::to_string(kMaxPatternLength));
    if (const std::string problem = unsupportedSyntax(entry); !problem.empty())
      throw ExpectationFileError(where(file, line) + ": '" + entry + "': " + problem);
    try {
      out.push_back({entry, std::regex(entry, std::regex::ECMAScript), {file, line}});
    } catch (const std::regex_error& e) {
      throw ExpectationFileError(where(file, line) + ": '" + entry + "' is not a regular expression (" + e.what() +
                                 ")");
    }
  });
  return out;
}

std::vector<ListedCase> parseCaseListText(const std::string& text, const std::string& file) {
  std::vector<ListedCase> out;
  forEachEntry(text, [&](const std::string& entry, int line) {
    if (!isCaseId(entry))
      throw ExpectationFileError(where(file, line) + ": '" + entry +
                                 "' is not a case id (lower-case letters, digits, '_' and '.')");
    out.push_back({entry, {file, line}});
  });
  return out;
}

Expectations readExpectations(const std::vector<std::filesystem::path>& fails,
                              const std::vector<std::filesystem::path>& flakes,
                              const std::vector<std::filesystem::path>& skips) {
  Expectations e;
  for (const auto& f : fails) parseFailsText(readWhole(f, "fails file"), f.string(), e.fails);
  for (const auto& f : flakes) {
    auto p = parsePatternsText(readWhole(f, "flakes file"), f.string());
    e.flakes.insert(e.flakes.end(), p.begin(), p.end());
  }
  for (const auto& f : skips) {
    auto p = parsePatternsText(readWhole(f, "skips file"), f.string());
    e.skips.insert(e.skips.end(), p.begin(), p.end());
  }
  return e;
}

std::vector<ListedCase> readCaseLists(const std::vector<std::filesystem::path>& lists) {
  std::vector<ListedCase> out;
  std::map<std::string, FileLine> seen;
  for (const auto& f : lists)
    for (ListedCase& c : parseCaseListText(readWhole(f, "case list"), f.string())) {
      const auto [it, added] = seen.emplace(c.id, c.from);
      if (!added)
        throw ExpectationFileError(where(c.from.file, c.from.line) + ": " + c.id + " is already listed at " +
                                   where(it->second.file, it->second.line));
      out.push_back(std::move(c));
    }
  return out;
}

const Pattern* firstMatch(const std::vector<Pattern>& patterns, const std::string& id) {
  for (const Pattern& p : patterns)
    if (std::regex_search(id, p.regex)) return &p;
  return nullptr;
}

}  // namespace voxref::conf
