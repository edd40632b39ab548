// The Pareto front of (cost, error) points, both to be minimised: the points
// no other point beats on one axis without losing on the other.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace spanlight::sweep {

struct ParetoPoint {
  double cost;
  double error;
};

// True when a is at least as good as b on both axes and better on one.
bool dominates(const ParetoPoint& a, const ParetoPoint& b);

// Indices of the front, by increasing cost (hence decreasing error). Of points
// that are equal on both axes only the first is kept; points with a NaN
// coordinate (not measured) are left out.
std::vector<std::size_t> pareto_front(std::span<const ParetoPoint> points);

}  // namespace spanlight::sweep
