#include "body_part.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "tube.hpp"

namespace spanlight::mesh_generator {

namespace {

// sign(x) |x|^e: the superellipse's coordinate for cos or sin x.
double signed_power(double x, double e) { return std::copysign(std::pow(std::abs(x), e), x); }

}  // namespace

IndexedMesh body_part(const BodyPart& part) {
  const glm::dvec3 axis = part.to - part.from;
  const glm::dvec3 along = glm::normalize(axis);
  const glm::dvec3 across = glm::normalize(part.seam_side - glm::dot(part.seam_side, along) * along);
  const glm::dvec3 around = glm::cross(along, across);  // across x around = along: rings run from `from` to `to`

  // The ellipse's perimeter (root-mean-square radius, within 4 % up to a 2:1 ellipse) in whole texture repeats.
  const double mean_radius = std::sqrt((part.radius_seam_side * part.radius_seam_side +
                                        part.radius_sideways * part.radius_sideways) / 2.0);
  const int u_repeats = std::max(1, static_cast<int>(std::lround(2.0 * std::numbers::pi * mean_radius / part.texture_size)));

  std::vector<Ring> rings;
  glm::dvec3 previous_seam_point = part.from;
  double v = part.v_offset;
  for (int i = 1; i <= part.rings; ++i) {
    const double angle = std::numbers::pi * i / (part.rings + 1);
    const double t = (1.0 - signed_power(std::cos(angle), part.roundness)) / 2.0;  // 0 at `from`, 1 at `to`
    const double width = signed_power(std::sin(angle), part.roundness) * (1.0 + (part.taper - 1.0) * t);
    Ring ring{part.from + t * axis, across, around, width * part.radius_seam_side, width * part.radius_sideways, 0.0};
    const glm::dvec3 seam_point = ring.centre + ring.radius_across * across;
    v += glm::length(seam_point - previous_seam_point) / part.texture_size;
    ring.v = v;
    rings.push_back(ring);
    previous_seam_point = seam_point;
  }
  const double v_end = v + glm::length(part.to - previous_seam_point) / part.texture_size;
  return capped_tube(rings, Pole{part.from, part.v_offset}, Pole{part.to, v_end}, part.segments, u_repeats);
}

}  // namespace spanlight::mesh_generator
