#include "float_model/raster.hpp"

#include <algorithm>

#include "float_model/clip.hpp"

namespace spanlight::float_model {

glm::dvec2 interpolate_uv(const ClipTriangle& triangle, const Fragment& fragment) {
  glm::dvec2 uv(0.0);
  for (std::size_t i = 0; i < 3; ++i) uv += fragment.beta[i] * triangle[i].uv;
  return uv;
}

glm::dvec4 interpolate_projector(const ClipTriangle& triangle, const Fragment& fragment, std::size_t projector) {
  glm::dvec4 strq(0.0);
  for (std::size_t i = 0; i < 3; ++i) strq += fragment.beta[i] * triangle[i].projector[projector];
  return strq;
}

UvDerivatives uv_derivatives(const ClipTriangle& triangle, const Fragment& fragment) {
  double d = 0.0;  // D = sum lambda_i / w_i
  for (std::size_t i = 0; i < 3; ++i) d += fragment.lambda[i] / triangle[i].position.w;
  const glm::dvec2 uv = interpolate_uv(triangle, fragment);
  UvDerivatives out{glm::dvec2(0.0), glm::dvec2(0.0)};
  for (std::size_t i = 0; i < 3; ++i) {
    const glm::dvec2 toward = (triangle[i].uv - uv) / (triangle[i].position.w * d);
    out.d_dx += fragment.dlambda_dx[i] * toward;
    out.d_dy += fragment.dlambda_dy[i] * toward;
  }
  return out;
}

namespace {

// floor(a / b) for b > 0, also for negative a.
std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

// The pixels whose centres lie within [lo, hi] subpixels, limited to [0, size).
std::pair<int, int> pixel_range(std::int64_t lo, std::int64_t hi, int size) {
  const std::int64_t half = subpixels_per_pixel / 2;
  const std::int64_t first = -floor_div(-(lo - half), subpixels_per_pixel);  // ceil((lo - half) / 256)
  const std::int64_t last = floor_div(hi - half, subpixels_per_pixel);
  return {static_cast<int>(std::clamp<std::int64_t>(first, 0, size)),
          static_cast<int>(std::clamp<std::int64_t>(last, -1, size - 1))};
}

// Calls visit(px, py, edges) for every covered pixel centre inside the viewport.
template <typename Visit>
void for_each_covered_pixel(const OrientedTriangle& triangle, int width, int height, Visit&& visit) {
  const auto [min_x, max_x] = std::minmax({triangle.v[0].x, triangle.v[1].x, triangle.v[2].x});
  const auto [min_y, max_y] = std::minmax({triangle.v[0].y, triangle.v[1].y, triangle.v[2].y});
  const auto [first_x, last_x] = pixel_range(min_x, max_x, width);
  const auto [first_y, last_y] = pixel_range(min_y, max_y, height);
  for (int py = first_y; py <= last_y; ++py) {
    for (int px = first_x; px <= last_x; ++px) {
      const auto edges = barycentric_edges(triangle, pixel_centre(px, py));
      if (covers(triangle, edges)) visit(px, py, edges);
    }
  }
}

}  // namespace

bool is_back_facing(const std::array<SnappedVertex, 3>& triangle) {
  // With y down, a positive signed area is clockwise as the image is seen.
  return twice_signed_area(triangle[0], triangle[1], triangle[2]) >= 0;
}

void rasterize_clipped(const ClipTriangle& triangle, Viewport viewport, scene::Cull cull, const FragmentVisitor& visit) {
  std::array<WindowPoint, 3> window{};
  std::array<SnappedVertex, 3> snapped{};
  for (std::size_t i = 0; i < 3; ++i) {
    window[i] = to_window(triangle[i].position, viewport.width, viewport.height);
    snapped[i] = snap(window[i]);
  }
  if (cull == scene::Cull::back && is_back_facing(snapped)) return;
  const auto oriented = orient(snapped);
  if (!oriented) return;  // zero area covers nothing

  // Oriented vertex k is the triangle's vertex source[k].
  const std::array<std::size_t, 3> source = oriented->swapped ? std::array<std::size_t, 3>{0, 2, 1}
                                                              : std::array<std::size_t, 3>{0, 1, 2};
  const double twice_area = static_cast<double>(oriented->twice_area);
  // Oriented vertex k's weight is its opposite edge's value, the edge a = v[k+1] -> b = v[k+2]:
  // dE/dx = -(b.y - a.y), dE/dy = b.x - a.x per subpixel, times 256 per pixel.
  std::array<double, 3> dlambda_dx{}, dlambda_dy{};
  for (std::size_t k = 0; k < 3; ++k) {
    const SnappedVertex& a = oriented->v[(k + 1) % 3];
    const SnappedVertex& b = oriented->v[(k + 2) % 3];
    const double per_pixel = static_cast<double>(subpixels_per_pixel) / twice_area;
    dlambda_dx[source[k]] = -static_cast<double>(b.y - a.y) * per_pixel;
    dlambda_dy[source[k]] = static_cast<double>(b.x - a.x) * per_pixel;
  }

  for_each_covered_pixel(*oriented, viewport.width, viewport.height,
                         [&](int px, int py, const std::array<EdgeValue, 3>& edges) {
    Fragment fragment{px, py, 0.0, {}, {}, dlambda_dx, dlambda_dy};
    for (std::size_t k = 0; k < 3; ++k) fragment.lambda[source[k]] = static_cast<double>(edges[k]) / twice_area;

    double sum_over_w = 0.0;
    for (std::size_t i = 0; i < 3; ++i) {
      fragment.depth += fragment.lambda[i] * window[i].z;
      fragment.beta[i] = fragment.lambda[i] / triangle[i].position.w;
      sum_over_w += fragment.beta[i];
    }
    for (double& beta : fragment.beta) beta /= sum_over_w;  // the exact per-pixel divide
    visit(triangle, fragment);
  });
}

void draw_triangle(const ClipTriangle& triangle, Viewport viewport, scene::Cull cull, const FragmentVisitor& visit) {
  for (const ClipTriangle& piece : clip_triangle(triangle)) rasterize_clipped(piece, viewport, cull, visit);
}

std::vector<std::pair<int, int>> covered_pixels(const SnappedVertex tri[3], int width, int height) {
  std::vector<std::pair<int, int>> pixels;
  if (const auto oriented = orient({tri[0], tri[1], tri[2]})) {
    for_each_covered_pixel(*oriented, width, height,
                           [&](int px, int py, const std::array<EdgeValue, 3>&) { pixels.emplace_back(px, py); });
  }
  return pixels;
}

}  // namespace spanlight::float_model
