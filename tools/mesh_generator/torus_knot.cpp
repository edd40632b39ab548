#include "torus_knot.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "tube.hpp"

namespace spanlight::mesh_generator {

namespace {

constexpr int p = 2, q = 3;  // turns around the torus's axis, and through its hole
constexpr double torus_radius = 1.0, winding_radius = 0.5, tube_radius = 0.3;
constexpr int rings = 180, segments = 12;  // 2 * rings * segments = 4320 triangles
constexpr int tiles_around = 2;             // texture repeats around the tube
constexpr double tiles_along = 16.0;       // along the whole knot: a whole number, so the loop's seam is continuous

glm::dvec3 knot_point(double angle) {
  const double r = torus_radius + winding_radius * std::cos(q * angle);
  return {r * std::cos(p * angle), r * std::sin(p * angle), winding_radius * std::sin(q * angle)};
}

glm::dvec3 knot_tangent(double angle) {
  const double r = torus_radius + winding_radius * std::cos(q * angle);
  const double dr = -q * winding_radius * std::sin(q * angle);
  return glm::normalize(glm::dvec3{dr * std::cos(p * angle) - p * r * std::sin(p * angle),
                                   dr * std::sin(p * angle) + p * r * std::cos(p * angle),
                                   q * winding_radius * std::cos(q * angle)});
}

}  // namespace

IndexedMesh torus_knot() {
  std::vector<Ring> tube;
  for (int i = 0; i < rings; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / rings;
    const glm::dvec3 centre = knot_point(angle);
    const glm::dvec3 along = knot_tangent(angle);
    // The ring's angle 0 points away from the knot's axis (z): a function of the angle
    // alone, so the frame comes back to itself after one loop. It is never undefined:
    // the tangent always turns around z (its part across the radius is p r, r >= 0.5),
    // so it is never parallel to `outward`.
    const glm::dvec3 outward{centre.x, centre.y, 0.0};
    const glm::dvec3 across = glm::normalize(outward - glm::dot(outward, along) * along);
    tube.push_back({centre, across, glm::cross(along, across), tube_radius, tube_radius, tiles_along * i / rings});
  }
  return looped_tube(tube, tiles_along, segments, tiles_around);
}

}  // namespace spanlight::mesh_generator
