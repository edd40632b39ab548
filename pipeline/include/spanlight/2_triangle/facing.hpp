// Stage 2d, facing (scene format 2, projectors[].facing_only): a triangle is lit
// by such a projector only when the projector's eye and the camera's eye lie
// strictly on the same side of the triangle's plane.
//
// No eye position is needed. For a perspective view the homogeneous (x, y, w)
// of a point X is K (X - eye) with K = diag(f / aspect, f, -1) R, and the
// projector's (s, t, q) = B3 K_j (X - eye_j) with det B3 = 1/4. So
//   det[(s, t, q)_i] = det(B3 K_j) det[X_i - eye_j],  det(B3 K_j) < 0,
// and det[X_i - eye_j] is the signed volume that says on which side of the
// plane eye_j lies. The camera's sign is the window orientation of the snapped
// triangle (w > 0 at every drawn vertex; window y points down, which flips it).
#pragma once

#include <algorithm>
#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "spanlight/1_vertex/transform.hpp"

namespace spanlight {

// The sign of det[(s, t, q)_0; (s, t, q)_1; (s, t, q)_2]: each value is brought
// below 2^20 by one common shift (the sign of a determinant does not change
// under a positive scale), so each of the six triple products is below 2^60 and
// their sum fits int64. Truncation can only move a determinant that is within
// a few units of 2^-20 of the largest entry cubed: an eye practically in the plane.
constexpr int projector_orientation(const Vec4Wide& a, const Vec4Wide& b, const Vec4Wide& c) {
  const std::int64_t in[3][3] = {{a.x, a.y, a.w}, {b.x, b.y, b.w}, {c.x, c.y, c.w}};
  std::uint64_t largest = 0;
  for (const auto& row : in)
    for (const std::int64_t x : row) {
      const std::uint64_t m = static_cast<std::uint64_t>(x < 0 ? -x : x);
      largest = m > largest ? m : largest;
    }
  const int shift = std::max(fixedpoint::bit_length(largest) - 20, 0);
  std::int64_t m[3][3];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) m[i][k] = in[i][k] >> shift;
  const std::int64_t det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return det > 0 ? 1 : (det < 0 ? -1 : 0);
}

// Whether the projector faces the triangle the camera sees, from the window
// orientation of its snapped vertices (window_area2 > 0: clockwise on screen)
// and the projector's (s, t, q) at the same three vertices.
constexpr bool faces_projector(std::int64_t window_area2, const Vec4Wide& a, const Vec4Wide& b, const Vec4Wide& c) {
  // Camera: sign det[(x, y, w)_i] = -sign(window area). Both K have the same
  // determinant sign, so same side <=> det_camera and det_projector agree.
  const int camera = window_area2 > 0 ? -1 : (window_area2 < 0 ? 1 : 0);
  const int projector = projector_orientation(a, b, c);
  return camera != 0 && camera == projector;
}

}  // namespace spanlight
