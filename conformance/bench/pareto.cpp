#include "conformance/bench/pareto.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace voxref::conf {
namespace {

bool valid(const TradeoffPoint& p) { return !std::isnan(p.cost) && !std::isnan(p.error); }

// q dominates p: no worse in both, strictly better in one.
bool dominates(const TradeoffPoint& q, const TradeoffPoint& p) {
  return q.cost <= p.cost && q.error <= p.error && (q.cost < p.cost || q.error < p.error);
}

std::string number(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

}  // namespace

std::vector<std::size_t> paretoFront(std::span<const TradeoffPoint> points) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!valid(points[i])) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j)
      dominated = j != i && valid(points[j]) && dominates(points[j], points[i]);
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
    if (points[a].error != points[b].error) return points[a].error > points[b].error;
    return a < b;
  });
  return front;
}

std::string frontCostSummary(std::span<const TradeoffPoint> points, std::span<const std::string> labels,
                             std::span<const std::size_t> front, std::string_view quantity) {
  const std::string q(quantity);
  if (front.empty()) return {};
  const std::size_t fast = front.front(), accurate = front.back();
  const TradeoffPoint& f = points[fast];
  const TradeoffPoint& a = points[accurate];
  if (f.cost == a.cost && f.error == a.error)
    return labels[fast] + " is both the fastest and the " + (q == "error" ? "most accurate" : "smallest");
  std::string s = "from " + labels[fast] + " to " + labels[accurate] + ": ";
  s += f.cost > 0.0 ? number("%.3g", a.cost / f.cost) + "x the time" : "from no time to " + number("%.3g s", a.cost);
  if (a.error == 0.0)
    s += " for zero " + q + " (from " + number("%.3g", f.error) + ")";
  else
    s += " for " + number("%.3g", f.error / a.error) + "x less " + q;
  return s;
}

}  // namespace voxref::conf
