// look_at: GLM's lookAt (right-handed, the eye looks down -z), built in integers.
//     f = normalize(target - eye), s = normalize(cross(f, up)), u = cross(s, f)
//     rows s, u, -f and translation (-dot(s, eye), -dot(u, eye), dot(f, eye))
// It returns a View (the rows and the eye); mat4(view) is GLM's matrix, and
// view * model subtracts the eye exactly before rotating, so write chains as
//     Mat4 clip_from_object = perspective(...) * (look_at(...) * mat4(model));
// (docs/poses.md measures what the other order, (P * mat4(V)) * M, would lose).
//
// Inputs are Q15.16 (Vec3Q16 raw) with |coordinate| < 2^14, as the scene's
// positions. target - eye and cross(target - eye, up) are exact, so s is the
// direction of an exact vector however close up comes to the view direction.
//
// Error of each row entry (units of 2^-30; the bounds of normalize() in normalize.hpp):
//   f (the row -f): 1, its input being exact and below 2^32;
//   s: 1.87, its input (up to 2^62) being rounded to 32 bits first;
//   u_x = s_y f_z - s_z f_y: 1.87 (|f_z| + |f_y|) + 1 (|s_y| + |s_z|) + 1/2 (rounding), likewise u_y, u_z.
// In mat4(view) the translations are exact products of those rows with eye, within
// sum_i (row error) |eye_i|; then one rounding per column, 2^-(frac_bits + 1) (mat4.hpp).
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/mat4.hpp"
#include "fixedpoint/normalize.hpp"
#include "fixedpoint/pose_status.hpp"
#include "fixedpoint/vec.hpp"

namespace fixedpoint {

// up is refused when the sine of its angle to the view direction is below 2^-20
// (the scene loader refuses below 1e-6 > 2^-20, so every scene it accepts passes).
// The sine is computed from the Q1.30 unit vectors, each component within 2^-28 of the exact one.
inline constexpr int min_view_up_sine_log2 = -20;

namespace detail {

constexpr bool within_pose_range(const Vec3Q16& v) {
  const auto inside = [](std::int32_t c) { return c > -pose_coordinate_limit && c < pose_coordinate_limit; };
  return inside(v.x) && inside(v.y) && inside(v.z);
}

// |cross(a, b)|^2 in Q.60 for unit vectors in Q1.30: each component of the Q2.60 cross
// product is rounded to Q.30 first (|component| <= 1 + 2^-28, so the squares sum below 2^62).
constexpr std::uint64_t sine_squared_q60(const Vec3Q30& a, const Vec3Q30& b) {
  const Vec3Wide w = cross(a, b);
  const auto x = static_cast<std::int32_t>(shift_right_rounded(w.x, 30));
  const auto y = static_cast<std::int32_t>(shift_right_rounded(w.y, 30));
  const auto z = static_cast<std::int32_t>(shift_right_rounded(w.z, 30));
  return static_cast<std::uint64_t>(mul_s32(x, x) + mul_s32(y, y) + mul_s32(z, z));
}

}  // namespace detail

// The camera's or projector's frame: rotation rows s, u, f (Q1.30, as normalize and
// the rounded cross product left them) and the eye, kept apart so that V * M can
// subtract the eye exactly before rotating (see operator* below).
struct View {
  Vec3Q30 s, u, f;
  Vec3Q16 eye;
  PoseStatus status;
};

constexpr View look_at(const Vec3Q16& eye, const Vec3Q16& target, const Vec3Q16& up) {
  const auto fail = [](PoseStatus status) { return View{{}, {}, {}, {}, status}; };
  if (!detail::within_pose_range(eye) || !detail::within_pose_range(target) || !detail::within_pose_range(up)) {
    return fail(PoseStatus::coordinate_out_of_range);
  }
  // |coordinates| < 2^30 raw, so the difference fits int32 exactly.
  const Vec3Q16 d{target.x - eye.x, target.y - eye.y, target.z - eye.z};
  if (d.x == 0 && d.y == 0 && d.z == 0) return fail(PoseStatus::eye_equals_target);
  if (up.x == 0 && up.y == 0 && up.z == 0) return fail(PoseStatus::up_is_zero);

  const Vec3Q30 f = normalize(Vec3Wide{d.x, d.y, d.z});
  const Vec3Q30 up_unit = normalize(Vec3Wide{up.x, up.y, up.z});
  // sin^2 < 2^-40, in Q.60: below 2^20.
  if (detail::sine_squared_q60(f, up_unit) < (std::uint64_t{1} << (60 + 2 * min_view_up_sine_log2))) {
    return fail(PoseStatus::up_parallel_to_view);
  }
  const Vec3Q30 s = normalize(cross(d, up));  // the direction of cross(f, up), from exact integers
  const Vec3Wide u_q60 = cross(s, f);
  const Vec3Q30 u{static_cast<std::int32_t>(shift_right_rounded(u_q60.x, 30)),
                  static_cast<std::int32_t>(shift_right_rounded(u_q60.y, 30)),
                  static_cast<std::int32_t>(shift_right_rounded(u_q60.z, 30))};
  return {s, u, f, eye, PoseStatus::ok};
}

// GLM's lookAt matrix itself: rotation entries in Q1.30, translations
// (-dot(s, eye), -dot(u, eye), dot(f, eye)) in Q.46 (Q1.30 x Q15.16), exact, then one rounding.
constexpr Mat4 mat4(const View& v) {
  if (v.status != PoseStatus::ok) return {{}, {}, v.status};
  constexpr int r = unit_frac_bits, t = unit_frac_bits + 16;
  const Scaled entries[16] = {
      {v.s.x, r}, {v.u.x, r}, {-std::int64_t{v.f.x}, r}, {0, 0},
      {v.s.y, r}, {v.u.y, r}, {-std::int64_t{v.f.y}, r}, {0, 0},
      {v.s.z, r}, {v.u.z, r}, {-std::int64_t{v.f.z}, r}, {0, 0},
      {-dot(v.s, v.eye), t}, {-dot(v.u, v.eye), t}, {dot(v.f, v.eye), t}, {1, 0},
  };
  return mat4_from_scaled(entries);
}

namespace detail {

// translate(-eye) * m, exact in int64 then rounded once per column: row i < 3 is
// m_i - eye_i m_3, at frac_bits + 16 (m * 2^16 < 2^45, eye_i m_3j < 2^30 * 2^29), so
// there is no cancellation error: each column is within half a unit of its last place.
constexpr Mat4 eye_relative(const Vec3Q16& eye, const Mat4& m) {
  if (m.status != PoseStatus::ok) return m;
  const std::int32_t e[3] = {eye.x, eye.y, eye.z};
  Scaled entries[16] = {};
  for (int col = 0; col < 4; ++col) {
    const std::int32_t w = m.m[col * 4 + 3];
    for (int row = 0; row < 4; ++row) {
      const std::int64_t shifted = std::int64_t{m.m[col * 4 + row]} * 65536;
      entries[col * 4 + row] = {row < 3 ? shifted - mul_s32(e[row], w) : shifted, m.frac_bits[col] + 16};
    }
  }
  return mat4_from_scaled(entries);
}

}  // namespace detail

// V * M = R * (translate(-eye) * M): the eye is subtracted exactly first, so an
// object near a far-away eye keeps its precision (mat4(v) * M would carry the
// rounding of R eye, relative to |eye| rather than to |M's translation - eye|).
// Then R (Q1.30 rows) times each column, exact in int64 (< 3 * 2^30 * 2^29), rounded once.
constexpr Mat4 operator*(const View& v, const Mat4& m) {
  if (v.status != PoseStatus::ok) return {{}, {}, v.status};
  const Mat4 x = detail::eye_relative(v.eye, m);
  if (x.status != PoseStatus::ok) return x;
  const Vec3Q30 rows[3] = {v.s, v.u, {-v.f.x, -v.f.y, -v.f.z}};
  Scaled entries[16] = {};
  for (int col = 0; col < 4; ++col) {
    const std::int32_t* c = &x.m[col * 4];
    const int frac = unit_frac_bits + x.frac_bits[col];
    for (int row = 0; row < 3; ++row) {
      entries[col * 4 + row] = {mul_s32(rows[row].x, c[0]) + mul_s32(rows[row].y, c[1]) + mul_s32(rows[row].z, c[2]), frac};
    }
    entries[col * 4 + 3] = {std::int64_t{c[3]} << unit_frac_bits, frac};
  }
  return mat4_from_scaled(entries);
}

}  // namespace fixedpoint
