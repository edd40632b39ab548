// The Pareto front on hand-made points, and its defining property on random ones.
#include <cmath>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "sweep/pareto.hpp"

using spanlight::sweep::dominates;
using spanlight::sweep::pareto_front;
using spanlight::sweep::ParetoPoint;

TEST_CASE("dominates needs at least as good on both axes and better on one", "[pareto]") {
  CHECK(dominates({1, 1}, {2, 2}));
  CHECK(dominates({1, 2}, {2, 2}));
  CHECK(dominates({2, 1}, {2, 2}));
  CHECK_FALSE(dominates({2, 2}, {2, 2}));  // equal: neither dominates
  CHECK_FALSE(dominates({1, 3}, {2, 2}));  // a trade, not a win
  CHECK_FALSE(dominates({3, 1}, {2, 2}));
}

TEST_CASE("the front of hand-made points, cheapest first", "[pareto]") {
  const std::vector<ParetoPoint> points{
      {1.0, 10.0},  // 0: front
      {2.0, 5.0},   // 1: front
      {3.0, 5.0},   // 2: same error as 1, costs more
      {2.0, 8.0},   // 3: same cost as 1, worse error
      {4.0, 1.0},   // 4: front
      {5.0, 1.0},   // 5: dominated by 4
      {0.5, 20.0},  // 6: front, the cheapest
      {NAN, 0.1},   // 7: not measured
      {6.0, 0.5},   // 8: front, the most accurate
  };
  CHECK(pareto_front(points) == std::vector<std::size_t>{6, 0, 1, 4, 8});
}

TEST_CASE("equal points count once, the first of them", "[pareto]") {
  const std::vector<ParetoPoint> points{{2, 2}, {1, 3}, {2, 2}, {1, 3}};
  CHECK(pareto_front(points) == std::vector<std::size_t>{1, 0});
}

TEST_CASE("degenerate inputs", "[pareto]") {
  CHECK(pareto_front(std::vector<ParetoPoint>{}).empty());
  CHECK(pareto_front(std::vector<ParetoPoint>{{NAN, 1}, {1, NAN}}).empty());
  CHECK(pareto_front(std::vector<ParetoPoint>{{3, 4}}) == std::vector<std::size_t>{0});
  // One point better on both axes than all others is the whole front.
  CHECK(pareto_front(std::vector<ParetoPoint>{{5, 5}, {0, 0}, {3, 1}}) == std::vector<std::size_t>{1});
  // Zero error (identical images) is a value like any other.
  CHECK(pareto_front(std::vector<ParetoPoint>{{5, 0}, {9, 0}, {1, 2}}) == std::vector<std::size_t>{2, 0});
}

TEST_CASE("on random points: no front point is dominated, every other point is", "[pareto]") {
  std::mt19937 rng(20240611);
  std::uniform_int_distribution<int> coordinate(0, 30);  // small range: many ties
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<ParetoPoint> points(40);
    for (ParetoPoint& p : points) p = {static_cast<double>(coordinate(rng)), static_cast<double>(coordinate(rng))};
    const std::vector<std::size_t> front = pareto_front(points);
    std::vector<bool> on(points.size(), false);
    for (std::size_t i : front) on[i] = true;
    for (std::size_t k = 1; k < front.size(); ++k) {
      CHECK(points[front[k - 1]].cost < points[front[k]].cost);    // strictly cheaper first
      CHECK(points[front[k - 1]].error > points[front[k]].error);  // and strictly less accurate
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      bool dominated = false, equal_to_front = false;
      for (std::size_t j = 0; j < points.size(); ++j) dominated |= dominates(points[j], points[i]);
      for (std::size_t f : front)
        equal_to_front |= f != i && points[f].cost == points[i].cost && points[f].error == points[i].error;
      if (on[i]) CHECK_FALSE(dominated);
      else CHECK((dominated || equal_to_front));
    }
  }
}
