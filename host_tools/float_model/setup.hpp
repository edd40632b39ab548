// Stage 3, setup: window coordinates, snapping to 1/256 pixel, integer edge
// functions and the top-left tie rule. This is the exact coverage rule the fixed
// pipeline must reproduce bit for bit; property tests call pixel_covered directly.
//
// Coordinates: y points down, row 0 is the top of the output image, and the
// centre of pixel (px, py) is at subpixel (px*256 + 128, py*256 + 128).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <glm/glm.hpp>

namespace spanlight::float_model {

inline constexpr std::int64_t subpixels_per_pixel = 256;

// A vertex position snapped to 1/256 pixel, y down.
struct SnappedVertex {
  std::int64_t x, y;
  friend bool operator==(const SnappedVertex&, const SnappedVertex&) = default;
};

// Edge-function products need about twice the bits of a coordinate. Vertices are
// not clipped in x and y, so after a near clip a vertex may land millions of
// pixels off screen (scenes/horizon.json does); 128-bit products keep every
// edge value exact for any coordinate snap() accepts.
using EdgeValue = __int128;

// Window coordinates of a clip-space point (GL viewport, y flipped so row 0 is on top).
struct WindowPoint {
  double x, y;  // pixels, y down
  double z;     // window depth (z/w + 1) / 2, in [0, 1] after clipping
};
WindowPoint to_window(const glm::dvec4& clip, int width, int height);

// Rounds to the nearest 1/256 pixel, halves away from zero (std::llround).
// Throws std::range_error beyond +-2^53 pixels, which no clipped scene reaches.
SnappedVertex snap(const WindowPoint& point);

// E(a, b, p) = (b.x - a.x)(p.y - a.y) - (b.y - a.y)(p.x - a.x); positive on the
// side where, with y down, the triangle a, b, c is when twice_area(a, b, c) > 0.
EdgeValue edge_function(const SnappedVertex& a, const SnappedVertex& b, const SnappedVertex& p);

// E(a, b, c): twice the signed area, with y down. Positive means the triangle is
// clockwise as seen in the output image (y down turns the usual sense around).
EdgeValue twice_signed_area(const SnappedVertex& a, const SnappedVertex& b, const SnappedVertex& c);

// The centre of pixel (px, py) in subpixels.
SnappedVertex pixel_centre(int px, int py);

// For an edge a -> b of a triangle whose inside has E > 0: true when a pixel
// centre exactly on it belongs to this triangle. Left edge: the inside is to its
// right (dE/dx = -(b.y - a.y) > 0). Top edge: horizontal with the inside below it
// (b.y == a.y and dE/dy = b.x - a.x > 0). As in Direct3D, seen in the output image.
bool is_top_left(const SnappedVertex& a, const SnappedVertex& b);

// A triangle with its vertices ordered so that every edge function is positive
// inside. `swapped` says vertices 1 and 2 were exchanged to get there, so the
// caller can reorder the attributes the same way.
struct OrientedTriangle {
  std::array<SnappedVertex, 3> v;
  EdgeValue twice_area;            // > 0
  std::array<bool, 3> top_left;    // edge i runs from v[i] to v[(i+1)%3]
  bool swapped;
};

// nullopt for a zero-area triangle, which covers nothing.
std::optional<OrientedTriangle> orient(const std::array<SnappedVertex, 3>& triangle);

// The three edge values at p, ordered as barycentric weights: element i belongs
// to vertex i (it is the edge opposite it), so lambda_i = e[i] / twice_area.
std::array<EdgeValue, 3> barycentric_edges(const OrientedTriangle& triangle, const SnappedVertex& p);

// The coverage rule: every edge value > 0, or == 0 on a top or left edge.
bool covers(const OrientedTriangle& triangle, const std::array<EdgeValue, 3>& edges);

// The whole rule on one pixel, for any winding: is the centre of (px, py) covered?
bool pixel_covered(const SnappedVertex tri[3], int px, int py);

}  // namespace spanlight::float_model
