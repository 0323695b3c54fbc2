#include "conformance/framework/report/junit_xml.h"

#include <map>
#include <sstream>

#include "conformance/framework/expectations/outcomes.h"

namespace voxref::conf {

std::string xmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t')
          out += ' ';
        else
          out += c;
    }
  return out;
}

namespace {

// How a case shows in junit.xml: its status, unless its outcome says the job does not fail on it.
enum class Shown { Pass, Failure, Error, Skipped };

Shown shown(const CaseResult& r, std::string& note) {
  if (const auto o = parseOutcome(r.outcome)) {
    if (*o == Outcome::ExpectedFail || *o == Outcome::KnownFlake) {
      note = r.outcome + ": ";
      return Shown::Skipped;
    }
    if (*o == Outcome::Flake) return Shown::Pass;
    if (*o == Outcome::UnexpectedImprovement) {
      note = r.outcome + ": the fails file expects this case to fail; remove it from there. ";
      return Shown::Failure;
    }
  }
  switch (r.status) {
    case Status::Fail:
      return Shown::Failure;
    case Status::Crash:
    case Status::Timeout:
      return Shown::Error;
    case Status::Skip:
      return Shown::Skipped;
    default:
      return Shown::Pass;
  }
}

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

}  // namespace

std::string junitXml(const std::vector<CaseResult>& results, const JunitOptions& options) {
  std::map<std::string, std::vector<const CaseResult*>> bySystem;
  int failedListed = 0, unlisted = 0;
  for (const CaseResult& r : results) {
    std::string note;
    const Shown s = shown(r, note);
    if (s == Shown::Failure || s == Shown::Error) {
      if (options.limit >= 0 && failedListed >= options.limit) {
        ++unlisted;
        continue;
      }
      ++failedListed;
    }
    bySystem[r.system].push_back(&r);
  }
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"voxref\">\n";
  for (const auto& [system, cases] : bySystem) {
    int failures = 0, errors = 0, skipped = 0;
    double seconds = 0.0;
    for (const CaseResult* r : cases) {
      std::string note;
      const Shown s = shown(*r, note);
      failures += s == Shown::Failure;
      errors += s == Shown::Error;
      skipped += s == Shown::Skipped;
      seconds += r->secondsGl + r->secondsEmulation + r->secondsReference;
    }
    x << "  <testsuite name=\"" << xmlEscape(system) << "\" tests=\"" << cases.size() << "\" failures=\"" << failures
      << "\" errors=\"" << errors << "\" skipped=\"" << skipped << "\" time=\"" << seconds << "\">\n";
    for (const CaseResult* r : cases) {
      const std::string id = options.idPrefix + r->id;
      x << "    <testcase classname=\"" << xmlEscape(system) << "\" name=\"" << xmlEscape(id) << "\" time=\""
        << r->secondsGl + r->secondsEmulation + r->secondsReference << "\">\n";
      x << "      <properties><property name=\"judged_by\" value=\"" << name(r->judgedBy) << "\"/>";
      if (!r->outcome.empty()) x << "<property name=\"outcome\" value=\"" << xmlEscape(r->outcome) << "\"/>";
      x << "</properties>\n";
      std::string note;
      const Shown s = shown(*r, note);
      std::string text = note + r->message;
      if (!options.linkTemplate.empty() && (s == Shown::Failure || s == Shown::Error)) {
        text += ' ';  // not " " + ...: GCC 12 at -O3 warns on that (-Wrestrict, a false positive)
        text += replaceAll(options.linkTemplate, "{{testcase}}", id);
      }
      const std::string msg = xmlEscape(text);
      switch (s) {
        case Shown::Failure:
          x << "      <failure message=\"" << msg << "\"/>\n";
          break;
        case Shown::Error:
          x << "      <error type=\"" << name(r->status) << "\" message=\"" << msg << "\"/>\n";
          break;
        case Shown::Skipped:
          x << "      <skipped message=\"" << msg << "\"/>\n";
          break;
        case Shown::Pass:
          break;
      }
      x << "      <system-out>";
      for (const OracleResult& o : r->oracles)
        x << xmlEscape(o.oracle + " " + std::string(name(o.verdict)) + ": " + o.summary) << "\n";
      x << "</system-out>\n    </testcase>\n";
    }
    x << "  </testsuite>\n";
  }
  if (unlisted > 0)
    x << "  <testsuite name=\"voxref\" tests=\"1\" failures=\"1\" errors=\"0\" skipped=\"0\" time=\"0\">\n"
      << "    <testcase classname=\"voxref\" name=\"voxref.failures_not_listed\" time=\"0\">\n"
      << "      <failure message=\"" << unlisted << " more failed case(s) not listed (limit " << options.limit
      << "); failures.csv lists every one\"/>\n    </testcase>\n  </testsuite>\n";
  x << "</testsuites>\n";
  return x.str();
}

}  // namespace voxref::conf
