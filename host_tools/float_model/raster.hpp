// Stage 4, raster (the fixed pipeline's `span`): the pixels a clipped triangle
// covers, and what is interpolated there. Every pixel of the triangle's bounding
// box (limited to the viewport) is tested with the exact edge rule of setup.hpp;
// there is no stepping, so nothing accumulates.
//
// Interpolation at a pixel:
//   lambda_i = E_i / 2A                          screen barycentrics from the snapped vertices
//   depth    = sum lambda_i * z_window_i         linear in screen space
//   beta_i   = (lambda_i / w_i) / sum_k (lambda_k / w_k)   perspective-correct weights
//   uv, (s, t, r, q) = sum beta_i * attribute_i
//
// Screen derivatives of uv (for the mipmap level of detail) come from the same
// mapping: uv = N / D with N = sum lambda_i uv_i / w_i and D = sum lambda_i / w_i,
// both affine in the pixel position, so
//   d uv / dx = sum_i (d lambda_i / dx) / w_i * (uv_i - uv) / D     (likewise for y),
// exact at the pixel centre; d lambda_i / dx is a constant of the snapped triangle.
#pragma once

#include <array>
#include <functional>
#include <utility>
#include <vector>

#include "float_model/setup.hpp"
#include "float_model/transform.hpp"
#include "scene/scene.hpp"

namespace spanlight::float_model {

struct Viewport {
  int width, height;
};

// One covered pixel of one triangle. Weights are in the triangle's own vertex
// order (whatever orientation setup chose internally).
struct Fragment {
  int x, y;
  double depth;                  // window depth, sum lambda_i z_i
  std::array<double, 3> lambda;  // screen-space barycentrics
  std::array<double, 3> beta;    // perspective-correct barycentrics
  std::array<double, 3> dlambda_dx, dlambda_dy;  // d lambda_i per pixel (y down), constant over the triangle
};

// d uv / dx and d uv / dy at the fragment, in uv units per pixel (y down).
struct UvDerivatives {
  glm::dvec2 d_dx, d_dy;
};

glm::dvec2 interpolate_uv(const ClipTriangle& triangle, const Fragment& fragment);
glm::dvec4 interpolate_projector(const ClipTriangle& triangle, const Fragment& fragment, std::size_t projector);
UvDerivatives uv_derivatives(const ClipTriangle& triangle, const Fragment& fragment);

// Called once per covered pixel with the (clipped) triangle it came from.
using FragmentVisitor = std::function<void(const ClipTriangle&, const Fragment&)>;

// Setup and raster of a triangle already inside near/far: window coordinates,
// snap, cull (`back` drops triangles clockwise in the output image), then every
// covered pixel.
void rasterize_clipped(const ClipTriangle& triangle, Viewport viewport, scene::Cull cull, const FragmentVisitor& visit);

// Clip, then rasterize each piece of the fan.
void draw_triangle(const ClipTriangle& triangle, Viewport viewport, scene::Cull cull, const FragmentVisitor& visit);

// True when the snapped triangle would be dropped by `back` culling
// (clockwise as seen in the output image; zero area counts as culled too).
bool is_back_facing(const std::array<SnappedVertex, 3>& triangle);

// Every pixel of a width x height viewport whose centre the triangle covers,
// row by row from the top. The same rule the renderer uses, for property tests.
std::vector<std::pair<int, int>> covered_pixels(const SnappedVertex tri[3], int width, int height);

}  // namespace spanlight::float_model
