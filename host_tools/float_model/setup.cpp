#include "float_model/setup.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace spanlight::float_model {

WindowPoint to_window(const glm::dvec4& clip, int width, int height) {
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;  // the exact divide
  return {
      (ndc.x * 0.5 + 0.5) * width,
      (1.0 - (ndc.y * 0.5 + 0.5)) * height,  // GL's y is up; row 0 is the top row
      (ndc.z + 1.0) * 0.5,
  };
}

namespace {

std::int64_t snap_coordinate(double pixels) {
  // 2^53 pixels * 256 = 2^61 subpixels: llround is defined, the difference of two
  // coordinates fits in 64 bits and products of differences in EdgeValue.
  constexpr double limit = 9007199254740992.0;  // 2^53
  if (!(std::fabs(pixels) < limit)) throw std::range_error("float_model: vertex too far outside the viewport to snap");
  return static_cast<std::int64_t>(std::llround(pixels * static_cast<double>(subpixels_per_pixel)));
}

}  // namespace

SnappedVertex snap(const WindowPoint& point) { return {snap_coordinate(point.x), snap_coordinate(point.y)}; }

EdgeValue edge_function(const SnappedVertex& a, const SnappedVertex& b, const SnappedVertex& p) {
  const EdgeValue dx = EdgeValue{b.x} - a.x;
  const EdgeValue dy = EdgeValue{b.y} - a.y;
  return dx * (EdgeValue{p.y} - a.y) - dy * (EdgeValue{p.x} - a.x);
}

EdgeValue twice_signed_area(const SnappedVertex& a, const SnappedVertex& b, const SnappedVertex& c) {
  return edge_function(a, b, c);
}

SnappedVertex pixel_centre(int px, int py) {
  return {std::int64_t{px} * subpixels_per_pixel + subpixels_per_pixel / 2,
          std::int64_t{py} * subpixels_per_pixel + subpixels_per_pixel / 2};
}

bool is_top_left(const SnappedVertex& a, const SnappedVertex& b) {
  const std::int64_t dy = b.y - a.y;
  const std::int64_t dx = b.x - a.x;
  const bool left = dy < 0;            // inside lies towards +x
  const bool top = dy == 0 && dx > 0;  // horizontal, inside lies towards +y (below)
  return left || top;
}

std::optional<OrientedTriangle> orient(const std::array<SnappedVertex, 3>& triangle) {
  OrientedTriangle out{triangle, twice_signed_area(triangle[0], triangle[1], triangle[2]), {}, false};
  if (out.twice_area == 0) return std::nullopt;
  if (out.twice_area < 0) {
    std::swap(out.v[1], out.v[2]);
    out.twice_area = -out.twice_area;
    out.swapped = true;
  }
  for (std::size_t i = 0; i < 3; ++i) out.top_left[i] = is_top_left(out.v[i], out.v[(i + 1) % 3]);
  return out;
}

std::array<EdgeValue, 3> barycentric_edges(const OrientedTriangle& t, const SnappedVertex& p) {
  // Edge i runs v[i] -> v[i+1]; the one opposite vertex i is edge (i+1)%3.
  return {edge_function(t.v[1], t.v[2], p), edge_function(t.v[2], t.v[0], p), edge_function(t.v[0], t.v[1], p)};
}

bool covers(const OrientedTriangle& t, const std::array<EdgeValue, 3>& edges) {
  for (std::size_t vertex = 0; vertex < 3; ++vertex) {
    const std::size_t edge = (vertex + 1) % 3;  // the edge opposite `vertex`
    const EdgeValue e = edges[vertex];
    if (e < 0 || (e == 0 && !t.top_left[edge])) return false;
  }
  return true;
}

bool pixel_covered(const SnappedVertex tri[3], int px, int py) {
  const auto oriented = orient({tri[0], tri[1], tri[2]});
  return oriented && covers(*oriented, barycentric_edges(*oriented, pixel_centre(px, py)));
}

}  // namespace spanlight::float_model
