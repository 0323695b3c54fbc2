#include "conformance/framework/report/junit_xml.h"

#include <map>
#include <sstream>

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

std::string junitXml(const std::vector<CaseResult>& results) {
  std::map<std::string, std::vector<const CaseResult*>> bySystem;
  for (const CaseResult& r : results) bySystem[r.system].push_back(&r);
  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"voxref\">\n";
  for (const auto& [system, cases] : bySystem) {
    int failures = 0, errors = 0, skipped = 0;
    double seconds = 0.0;
    for (const CaseResult* r : cases) {
      failures += r->status == Status::Fail;
      errors += r->status == Status::Crash || r->status == Status::Timeout;
      skipped += r->status == Status::Skip;
      seconds += r->secondsGl + r->secondsEmulation + r->secondsReference;
    }
    x << "  <testsuite name=\"" << xmlEscape(system) << "\" tests=\"" << cases.size() << "\" failures=\"" << failures
      << "\" errors=\"" << errors << "\" skipped=\"" << skipped << "\" time=\"" << seconds << "\">\n";
    for (const CaseResult* r : cases) {
      x << "    <testcase classname=\"" << xmlEscape(system) << "\" name=\"" << xmlEscape(r->id) << "\" time=\""
        << r->secondsGl + r->secondsEmulation + r->secondsReference << "\">\n";
      x << "      <properties><property name=\"judged_by\" value=\"" << name(r->judgedBy) << "\"/></properties>\n";
      const std::string msg = xmlEscape(r->message);
      switch (r->status) {
        case Status::Fail:
          x << "      <failure message=\"" << msg << "\"/>\n";
          break;
        case Status::Crash:
        case Status::Timeout:
          x << "      <error type=\"" << name(r->status) << "\" message=\"" << msg << "\"/>\n";
          break;
        case Status::Skip:
          x << "      <skipped message=\"" << msg << "\"/>\n";
          break;
        default:
          break;
      }
      x << "      <system-out>";
      for (const OracleResult& o : r->oracles)
        x << xmlEscape(o.oracle + " " + std::string(name(o.verdict)) + ": " + o.summary) << "\n";
      x << "</system-out>\n    </testcase>\n";
    }
    x << "  </testsuite>\n";
  }
  x << "</testsuites>\n";
  return x.str();
}

}  // namespace voxref::conf
