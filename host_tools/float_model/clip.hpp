// Stage 2, clip: against the near (z >= -w) and far (z <= w) planes in clip
// space, Sutherland–Hodgman, every attribute interpolated linearly in clip
// space; the polygon that is left is fan-triangulated. There is no x/y
// clipping: coverage is limited to the viewport by the rasterizer, and the
// edge functions are evaluated wide enough not to overflow (setup.hpp).
#pragma once

#include <vector>

#include "float_model/transform.hpp"

namespace spanlight::float_model {

// The point a fraction `t` of the way from a to b, every attribute alike.
ClipVertex lerp(const ClipVertex& a, const ClipVertex& b, double t);

// Keeps the part of the polygon where `distance(v) >= 0`.
// distance is linear in clip space, so the crossing point is exact.
enum class ClipPlane { near, far };
std::vector<ClipVertex> clip_polygon(const std::vector<ClipVertex>& polygon, ClipPlane plane);

// The triangle clipped to near and far, as a fan of 0..(n-2) triangles
// (0 when it lies wholly outside; 1 when it lies wholly inside).
std::vector<ClipTriangle> clip_triangle(const ClipTriangle& triangle);

}  // namespace spanlight::float_model
