// Stage 1e, closed solids: an object drawn without culling whose mesh is a
// closed solid (ObjectData::closed) shows only its front faces to an eye
// outside it. Along a pixel's ray the surface is met first where the ray
// enters, and on screen every pixel a back face covers is covered by a front
// face as well (the signed count of a closed surface's triangles over a point
// is zero, and the fill rule counts a pixel centre on an edge as a point beside
// it). So when the object is wholly in front of the near plane (the eye is
// outside it and no face is cut open) and the view keeps its winding (no
// mirror), draw_pass culls its back faces: the picture is the nearest surface
// as before, up to depth ties between a face and one behind it.
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "spanlight/1_vertex/vertex_cache.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

// Whether the view draws the object's outward faces counter-clockwise, as cull "back" keeps them:
// the sign of the determinant of to_clip's rows x, y, w over x, y, z. Those rows are K (V M), K the
// projection's 3 x 3 (a perspective's has w = -z: det K < 0), so the determinant is negative
// unless the model or view mirrors. Each row is shifted down until its entries are at most 2^14
// (floors: each moves by under one unit), so the determinant (at most 6 * 2^42) moves by under
// 9 * 2^29 + 18 * 2^14 + 6 < 2^32.2 (cofactors, pairs, the triple): beyond 2^33 its sign is the
// exact one. A view that flattens the object (or an orthographic one, w constant) gives less
// and keeps both sides.
constexpr bool view_keeps_winding(const Mat4Block& to_clip) {
  std::int32_t r[3][3];
  const int rows[3] = {0, 1, 3};
  for (int i = 0; i < 3; ++i) {
    std::uint32_t largest = 0;
    for (int j = 0; j < 3; ++j) {
      const std::int32_t x = to_clip.m[j * 4 + rows[i]];
      const std::uint32_t magnitude = x < 0 ? 0u - static_cast<std::uint32_t>(x) : static_cast<std::uint32_t>(x);
      largest = magnitude > largest ? magnitude : largest;
    }
    const int bits = fixedpoint::bit_length32(largest);
    const int down = bits > 14 ? bits - 14 : 0;
    for (int j = 0; j < 3; ++j) r[i][j] = to_clip.m[j * 4 + rows[i]] >> down;  // |.| <= 2^14
  }
  // Each 2 x 2 minor at most 2^29, each term at most 2^43.
  auto minor = [&](int a, int b) { return r[1][a] * r[2][b] - r[1][b] * r[2][a]; };
  const std::int64_t det = fixedpoint::mul_s32_setup(r[0][0], minor(1, 2)) - fixedpoint::mul_s32_setup(r[0][1], minor(0, 2)) +
                           fixedpoint::mul_s32_setup(r[0][2], minor(0, 1));
  return det < -(std::int64_t{1} << 33);
}

// Whether this pass may cull the back faces of an object drawn without culling (see above).
[[gnu::noinline]] constexpr bool closed_and_outside(const ObjectData& object, const Mat4Block& to_clip, std::int64_t guard) {
  return object.cull == Cull::none && object.closed && view_keeps_winding(to_clip) &&
         object_before_near(object.bounds, to_clip, guard);
}

}  // namespace spanlight
