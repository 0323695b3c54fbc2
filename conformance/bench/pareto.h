// The Pareto front of accuracy-against-time measurements: the variants that no other variant
// beats in both time and error. Pure functions, no I/O; what `voxref bench` marks in its plots.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace voxref::conf {

// One measured variant: its cost (seconds per frame or per decode) and its error (max abs, RMSE
// or wrong-voxel share; smaller is better). Both are meant to be finite and >= 0.
struct TradeoffPoint {
  double cost = 0.0;
  double error = 0.0;
};

// Indices of the points on the Pareto front, ordered by cost ascending (error descending along
// the front), ties in cost and error broken by index. A point is on the front unless another
// point is no worse in both cost and error and strictly better in at least one: two points with
// identical cost and error are both on the front; of two points with equal cost the one with
// the larger error is off it. A point with a NaN coordinate is never on the front and never
// dominates another. An empty input gives an empty front. O(n^2): n is a handful of variants.
std::vector<std::size_t> paretoFront(std::span<const TradeoffPoint> points);

// What going along the front costs, from its fastest point to its most accurate one:
// "from A to B: 3.2x the time for 40x less error", "... for zero error (from 0.004)", or, for a
// front of one point, "A is both the fastest and the most accurate". `labels` name the points
// (same size as points); `front` is paretoFront(points); `quantity` names what the error axis
// holds ("error", or "memory" for a size-against-time front: "... for 2x less memory", "A is both
// the fastest and the smallest"). Empty when the front is empty.
std::string frontCostSummary(std::span<const TradeoffPoint> points, std::span<const std::string> labels,
                             std::span<const std::size_t> front, std::string_view quantity = "error");

}  // namespace voxref::conf
