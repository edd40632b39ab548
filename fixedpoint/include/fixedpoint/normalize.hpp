// Unit vectors in Q1.30 from exact integer vectors, for the pose builders.
// Only the direction of the input matters, so it may have any scale (a
// difference of Q15.16 points, an exact int64 cross product).
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/divide.hpp"
#include "fixedpoint/isqrt.hpp"
#include "fixedpoint/q.hpp"

namespace fixedpoint {

struct Vec3Q30 {  // a direction; 1.0 = 2^30
  std::int32_t x, y, z;
};

inline constexpr int unit_frac_bits = 30;

struct Vec3Wide {  // an exact integer vector (scale given by whoever made it)
  std::int64_t x, y, z;
};

namespace detail {

constexpr std::int32_t with_sign(std::int64_t sign_of, std::int64_t magnitude) {
  return static_cast<std::int32_t>(sign_of < 0 ? -magnitude : magnitude);
}

}  // namespace detail

// v / |v| in Q1.30 for a non-zero v (a zero v gives zero). Error of each component
// against the exact v_i / |v|, in units of 2^-30:
//   <= 1/2 (|u_i| + 1) + 2^-29 <= 1   when every |v_i| < 2^32: scaling by 2^k is exact,
//        |v| is rounded to nearest integer at >= 2^30 (relative 2^-31) and each quotient
//        is rounded once (2^-31); 2^-29 covers the truncated squares (relative < 2^-59);
//   <= 1 + sqrt(3)/2 < 1.87          otherwise: v is first rounded to 32 bits, moving its
//        direction by at most 2 |rounding| / |v| <= 2 (sqrt(3)/2) / 2^31.
inline constexpr double normalize_error_narrow_input = 1.0;  // units of 2^-30, every |v_i| < 2^32
inline constexpr double normalize_error_wide_input = 1.87;   // units of 2^-30, any v
constexpr Vec3Q30 normalize(const Vec3Wide& v) {
  const std::uint64_t a[3] = {detail::magnitude(v.x), detail::magnitude(v.y), detail::magnitude(v.z)};
  const std::uint64_t largest = a[0] > a[1] ? (a[0] > a[2] ? a[0] : a[2]) : (a[1] > a[2] ? a[1] : a[2]);
  if (largest == 0) return {0, 0, 0};
  // Scale so the largest magnitude lies in [2^31, 2^32): exact left shift, or a right
  // shift rounded half up, one bit further when rounding would carry into bit 32.
  int shift = bit_length(largest) - 32;
  if (shift > 0 && ((largest >> (shift - 1)) + 1) >> 1 > 0xFFFFFFFFu) ++shift;
  std::uint32_t w[3] = {};
  for (int i = 0; i < 3; ++i) {
    w[i] = static_cast<std::uint32_t>(shift > 0 ? ((a[i] >> (shift - 1)) + 1) >> 1 : a[i] << -shift);
  }
  // |w|^2 / 4 in [2^60, 3 * 2^62): each square is < 2^64 and each quarter < 2^62.
  const std::uint64_t quarter_norm2 = (mul_u32(w[0], w[0]) >> 2) + (mul_u32(w[1], w[1]) >> 2) + (mul_u32(w[2], w[2]) >> 2);
  const auto half_length = static_cast<std::uint32_t>(isqrt_rounded(quarter_norm2));  // ~|w|/2, in [2^30, 2^31.8)
  // u_i = w_i / |w| * 2^30 = w_i * 2^29 / (|w|/2); the quotient is <= 2^30 (1 + 2^-30) < 2^32.
  return {detail::with_sign(v.x, divide_rounded(static_cast<std::int64_t>(std::uint64_t{w[0]} << 29), half_length)),
          detail::with_sign(v.y, divide_rounded(static_cast<std::int64_t>(std::uint64_t{w[1]} << 29), half_length)),
          detail::with_sign(v.z, divide_rounded(static_cast<std::int64_t>(std::uint64_t{w[2]} << 29), half_length))};
}

// The exact cross product of two int32 vectors (Vec3Q16, Vec3Q30, ...): each
// product is < 2^62 in magnitude, so each difference fits int64. Its scale is the
// sum of the inputs' (Q16 x Q16 -> Q32, Q30 x Q30 -> Q60).
template <typename A, typename B>
constexpr Vec3Wide cross(const A& a, const B& b) {
  return {mul_s32(a.y, b.z) - mul_s32(a.z, b.y), mul_s32(a.z, b.x) - mul_s32(a.x, b.z),
          mul_s32(a.x, b.y) - mul_s32(a.y, b.x)};
}

// The exact dot product of two int32 vectors whose products stay below 2^61 in magnitude
// (a direction <= 1 + 2^-28 in Q1.30 and a Q15.16 point below 2^14), so the sum fits.
template <typename A, typename B>
constexpr std::int64_t dot(const A& a, const B& b) {
  return mul_s32(a.x, b.x) + mul_s32(a.y, b.y) + mul_s32(a.z, b.z);
}

}  // namespace fixedpoint
