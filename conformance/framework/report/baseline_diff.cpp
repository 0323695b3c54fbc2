#include "conformance/framework/report/baseline_diff.h"

#include <map>
#include <ostream>

namespace voxref::conf {
namespace {

bool failing(Status s) { return s == Status::Fail || s == Status::Crash || s == Status::Timeout; }

std::vector<FigureMove> movedFigures(const CaseResult& before, const CaseResult& after) {
  std::vector<FigureMove> moves;
  for (const OracleResult& a : after.oracles)
    for (const OracleResult& b : before.oracles) {
      if (a.oracle != b.oracle || !a.figures.is_object() || !b.figures.is_object()) continue;
      for (const auto& [key, value] : a.figures.items()) {
        const auto old = b.figures.find(key);
        if (old == b.figures.end() || !value.is_number() || !old->is_number()) continue;
        const double x = old->get<double>(), y = value.get<double>();
        if (x != y) moves.push_back({a.oracle, key, x, y});
      }
    }
  return moves;
}

nlohmann::json changesJson(const std::vector<CaseChange>& changes) {
  nlohmann::json list = nlohmann::json::array();
  for (const CaseChange& c : changes) {
    nlohmann::json moved = nlohmann::json::array();
    for (const FigureMove& m : c.moved)
      moved.push_back({{"oracle", m.oracle}, {"figure", m.figure}, {"before", m.before}, {"after", m.after}});
    list.push_back({{"id", c.id}, {"before", name(c.before)}, {"after", name(c.after)}, {"figures_moved", moved}});
  }
  return list;
}

void printChanges(std::ostream& out, const char* label, const std::vector<CaseChange>& changes) {
  for (const CaseChange& c : changes) {
    out << "  " << label << "  " << c.id << ": " << name(c.before) << " -> " << name(c.after);
    for (const FigureMove& m : c.moved)
      out << "; " << m.oracle << "." << m.figure << " " << m.before << " -> " << m.after;
    out << "\n";
  }
}

}  // namespace

BaselineDiff compareWithBaseline(const std::vector<CaseResult>& baseline, const std::vector<CaseResult>& current) {
  std::map<std::string, const CaseResult*> before;
  for (const CaseResult& r : baseline) before[r.id] = &r;
  BaselineDiff d;
  for (const CaseResult& now : current) {
    const auto it = before.find(now.id);
    if (it == before.end()) {
      d.added.push_back(now.id);
      continue;
    }
    const CaseResult& old = *it->second;
    before.erase(it);
    ++d.compared;
    CaseChange c{now.id, old.status, now.status, movedFigures(old, now)};
    if (failing(c.after) && !failing(c.before))
      d.newlyFailing.push_back(std::move(c));
    else if (c.after == Status::Warn && c.before == Status::Pass)
      d.newlyWarning.push_back(std::move(c));
    else if (failing(c.before) && (c.after == Status::Pass || c.after == Status::Warn))
      d.fixed.push_back(std::move(c));
    else if (c.before != c.after)
      d.otherStatus.push_back(std::move(c));
    else if (!c.moved.empty())
      d.figuresMoved.push_back(std::move(c));
  }
  for (const CaseResult& r : baseline)
    if (before.count(r.id)) d.missing.push_back(r.id);
  return d;
}

nlohmann::json baselineJson(const BaselineDiff& d, const std::string& baselineFile) {
  return {{"file", baselineFile},
          {"regressed", d.regressed()},
          {"compared", d.compared},
          {"newly_failing", changesJson(d.newlyFailing)},
          {"newly_warning", changesJson(d.newlyWarning)},
          {"fixed", changesJson(d.fixed)},
          {"other_status_changes", changesJson(d.otherStatus)},
          {"figures_moved", changesJson(d.figuresMoved)},
          {"added", d.added},
          {"missing", d.missing}};
}

void printBaselineDiff(std::ostream& out, const BaselineDiff& d, const std::string& baselineFile) {
  out << "baseline " << baselineFile << ": " << d.compared << " case(s) compared, " << d.newlyFailing.size()
      << " newly failing, " << d.newlyWarning.size() << " newly warning, " << d.fixed.size() << " fixed, "
      << d.otherStatus.size() << " other status change(s), " << d.figuresMoved.size() << " with figures moved, "
      << d.added.size() << " new, " << d.missing.size() << " not in this run\n";
  printChanges(out, "REGRESSED", d.newlyFailing);
  printChanges(out, "REGRESSED", d.newlyWarning);
  printChanges(out, "fixed    ", d.fixed);
  printChanges(out, "changed  ", d.otherStatus);
  printChanges(out, "moved    ", d.figuresMoved);
}

}  // namespace voxref::conf
