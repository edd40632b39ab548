// How far a pixel lies inside a convex polygon in window coordinates, for tests
// that only judge pixels clearly inside or outside a drawn outline.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace spanlight::test_support {

// The smallest signed distance (pixels) of p to the polygon's edges: > 0
// inside, < 0 outside. Either winding; zero-length edges are skipped.
inline double inside_distance(const std::vector<glm::dvec2>& polygon, glm::dvec2 p) {
  double area2 = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    area2 += a.x * b.y - b.x * a.y;
  }
  // y down: a polygon clockwise on screen has a positive shoelace sum here;
  // the edge function d x (p - a) is positive inside for that orientation.
  const double orientation = area2 > 0 ? 1.0 : -1.0;
  double smallest = 1e300;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()], d = b - a;
    const double length = std::hypot(d.x, d.y);
    if (length == 0.0) continue;
    smallest = std::min(smallest, orientation * (d.x * (p.y - a.y) - d.y * (p.x - a.x)) / length);
  }
  return smallest;
}

}  // namespace spanlight::test_support
