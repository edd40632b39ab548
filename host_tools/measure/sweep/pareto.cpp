#include "sweep/pareto.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace spanlight::sweep {

bool dominates(const ParetoPoint& a, const ParetoPoint& b) {
  return a.cost <= b.cost && a.error <= b.error && (a.cost < b.cost || a.error < b.error);
}

std::vector<std::size_t> pareto_front(std::span<const ParetoPoint> points) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isnan(points[i].cost) && !std::isnan(points[i].error)) order.push_back(i);
  // Cheapest first; at equal cost the smaller error, then the earlier point.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (points[a].cost != points[b].cost) return points[a].cost < points[b].cost;
    return points[a].error < points[b].error;
  });
  std::vector<std::size_t> front;
  for (std::size_t i : order) {
    // Everything before i costs no more; i is on the front only if it beats all of their errors.
    if (front.empty() || points[i].error < points[front.back()].error) front.push_back(i);
  }
  return front;
}

}  // namespace spanlight::sweep
