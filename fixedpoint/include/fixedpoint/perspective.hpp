// perspective: GLM's perspective (right-handed, clip depth in [-w, w]), in integers.
//     P00 = cot(fovy/2) / aspect   P11 = cot(fovy/2)   P23 = -1
//     P22 = -(far + near) / (far - near)   P32 = -2 far near / (far - near)
// (P_col,row, column-major as GLM stores it.)
//
// Inputs: fovy in Turns, within [2^-16, 1/2 - 2^-16] turn (0.0055 to 179.9945
// degrees: cot(fovy/2) stays in [2^-14.35, 2^14.35]); aspect = width / height with
// integers in [1, 2^32) (a Q15.16 aspect a is {a.raw(), 65536}); 0 < near < far < 2^14
// in Q15.16.
//
// cot(fovy/2): with h = fovy.raw, the half angle is h * pi / 2^32 radians. For
// fovy <= 1/4 turn, z = h pi / 2^32 and cot = C(z^2) / (z S(z^2)); otherwise
// z = (2^31 - h) pi / 2^32 = pi/2 - fovy/2 and cot = z S(z^2) / C(z^2) (trig.hpp).
// Relative error bounds, in units of 2^-32 (derived factor by factor):
//   C's error / C_min (2^-32 / 0.707)   1.42    S's error / S_min (2^-33.4 / 0.90)   0.42
//   K = round(pi 2^30)                   0.17    four roundings to 32 bits (C, z, S, z*S) 4
//   the reciprocal (1.878e-9)            8.07
//   P11: 14.08, so <= 3.28e-9; P00 adds the products by height and width: 16.08, <= 3.75e-9.
//   P22: the reciprocal of far - near only: 1.878e-9; P32: that and far*near's rounding: 2.12e-9.
// Then one rounding per column, 2^-(frac_bits + 1): each of P00, P11 and P32 has a
// column to itself, and P22 shares its column with -1 only.
#pragma once

#include <cstdint>

#include "fixedpoint/magnitude32.hpp"
#include "fixedpoint/mat4.hpp"
#include "fixedpoint/pose_status.hpp"
#include "fixedpoint/q.hpp"
#include "fixedpoint/trig.hpp"
#include "fixedpoint/vec.hpp"

namespace fixedpoint {

struct Aspect {
  std::uint32_t width, height;  // aspect = width / height
};

// The relative error bounds above, for tests and for bounds derived from them.
inline constexpr double p11_relative_error = 3.28e-9;  // 14.08 * 2^-32 = 3.278e-9
inline constexpr double p00_relative_error = 3.75e-9;  // 16.08 * 2^-32 = 3.744e-9
inline constexpr double p22_relative_error = 1.878e-9;
inline constexpr double p32_relative_error = 2.12e-9;  // 1.878e-9 + 2^-32 = 2.111e-9

// A Q15.16 aspect (a projector's): a non-positive one gives width 0, refused by perspective.
constexpr Aspect aspect_from_q16(const q16& a) { return {a.raw() > 0 ? static_cast<std::uint32_t>(a.raw()) : 0u, 1u << 16}; }

inline constexpr std::uint32_t min_fovy_raw = 1u << 16;                  // 2^-16 turn
inline constexpr std::uint32_t max_fovy_raw = (1u << 31) - (1u << 16);   // 1/2 - 2^-16 turn

constexpr Mat4 perspective(Turns fovy, Aspect aspect, const q16& near, const q16& far) {
  const auto fail = [](PoseStatus s) { return Mat4{{}, {}, s}; };
  if (fovy.raw < min_fovy_raw || fovy.raw > max_fovy_raw) return fail(PoseStatus::fovy_out_of_range);
  if (aspect.width == 0 || aspect.height == 0) return fail(PoseStatus::aspect_not_positive);
  if (near.raw() <= 0) return fail(PoseStatus::near_not_positive);
  if (far.raw() >= pose_coordinate_limit || near.raw() >= pose_coordinate_limit) return fail(PoseStatus::coordinate_out_of_range);
  if (far.raw() <= near.raw()) return fail(PoseStatus::far_not_beyond_near);

  // cot(fovy/2) = num / den.
  const bool narrow = fovy.raw <= (1u << 30);  // fovy <= 90 degrees
  const detail::ReducedAngle z = detail::reduced_angle(narrow ? fovy.raw : (1u << 31) - fovy.raw);
  const Magnitude32 c = magnitude32(static_cast<std::uint64_t>(detail::cos_q60(z.w_q31)), -detail::poly_frac_bits);
  const Magnitude32 z_s = magnitude32(z.z_q62, -62) *
                          magnitude32(static_cast<std::uint64_t>(detail::sin_over_z_q60(z.w_q31)), -detail::poly_frac_bits);
  const Magnitude32 num = narrow ? c : z_s;
  const Magnitude32 den = narrow ? z_s : c;
  const Scaled p11 = quotient(num, den, false);
  const Scaled p00 = quotient(num * magnitude32(aspect.height, 0), den * magnitude32(aspect.width, 0), false);

  // Depth: the Q15.16 scales cancel in P22 and leave 2^-16 in P32.
  const auto n = static_cast<std::uint32_t>(near.raw()), f = static_cast<std::uint32_t>(far.raw());
  const Reciprocal inverse_depth = reciprocal<8, 2>(f - n);  // f - n >= 1
  const auto sum = static_cast<std::int64_t>(mul_u32(f + n, inverse_depth.mantissa));  // < 2^31 * 2^31
  const Scaled p22 = {-sum, inverse_depth.shift};
  const Magnitude32 two_f_n = magnitude32(mul_u32(f, n), 1 - 2 * 16);
  const Scaled p32 = quotient(two_f_n, magnitude32(f - n, -16), true);

  const Scaled entries[16] = {
      p00, {0, 0}, {0, 0}, {0, 0},
      {0, 0}, p11, {0, 0}, {0, 0},
      {0, 0}, {0, 0}, p22, {-1, 0},
      {0, 0}, {0, 0}, p32, {0, 0},
  };
  return mat4_from_scaled(entries);
}

}  // namespace fixedpoint
