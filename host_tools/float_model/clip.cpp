#include "float_model/clip.hpp"

namespace spanlight::float_model {

ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t) {
  ClipVertex out;
  out.position = a.position + (b.position - a.position) * t;
  out.uv = a.uv + (b.uv - a.uv) * t;
  out.projector.resize(a.projector.size());
  for (std::size_t j = 0; j < a.projector.size(); ++j) {
    out.projector[j] = a.projector[j] + (b.projector[j] - a.projector[j]) * t;
  }
  return out;
}

namespace {

// Signed distance to the plane, >= 0 inside: near is z + w >= 0, far is w - z >= 0.
double inside_distance(const glm::dvec4& clip, ClipPlane plane) {
  return plane == ClipPlane::near ? clip.z + clip.w : clip.w - clip.z;
}

}  // namespace

std::vector<ClipVertex> clip_polygon(const std::vector<ClipVertex>& polygon, ClipPlane plane) {
  std::vector<ClipVertex> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const ClipVertex& current = polygon[i];
    const ClipVertex& next = polygon[(i + 1) % polygon.size()];
    const double d_current = inside_distance(current.position, plane);
    const double d_next = inside_distance(next.position, plane);
    if (d_current >= 0.0) out.push_back(current);
    // The edge crosses the plane strictly: add the crossing point. A vertex exactly
    // on the plane is kept above and needs no extra point.
    if ((d_current > 0.0 && d_next < 0.0) || (d_current < 0.0 && d_next > 0.0)) {
      out.push_back(lerp(current, next, d_current / (d_current - d_next)));
    }
  }
  return out;
}

std::vector<ClipTriangle> clip_triangle(const ClipTriangle& triangle) {
  std::vector<ClipVertex> polygon(triangle.begin(), triangle.end());
  polygon = clip_polygon(polygon, ClipPlane::near);
  polygon = clip_polygon(polygon, ClipPlane::far);
  std::vector<ClipTriangle> fan;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    fan.push_back({polygon[0], polygon[i], polygon[i + 1]});
  }
  return fan;
}

}  // namespace spanlight::float_model
