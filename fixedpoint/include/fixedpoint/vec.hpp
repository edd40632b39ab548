// The vertex transform of the pipeline: a block-floating-point 4x4 matrix times
// a Q15.16 position, exact in int64 and rounded once.
//
// Mat4Block holds int32 mantissas with ONE shared exponent:
//     value(col, row) = m[col * 4 + row] * 2^-frac_bits      (column-major, like GLM)
// with |m| < 2^29 and frac_bits in [0, 60]; mat4_block_from_doubles picks the
// largest frac_bits that keeps that bound, so the largest entry uses 29 bits.
//
// Freestanding and constexpr; the double-based helpers are meant for the host
// (they also compile for the target, via soft or hard float).
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/q.hpp"

namespace fixedpoint {

inline constexpr std::int32_t mat4_block_entry_limit = std::int32_t{1} << 29;  // |m[i]| < this
inline constexpr int mat4_block_max_frac_bits = 60;
// What the pipeline accepts: below 16 fraction bits an entry may be >= 2^13 and
// transform()'s Q31.32 result could saturate (see transform below).
inline constexpr int mat4_block_pipeline_min_frac_bits = 16;

struct Mat4Block {
  std::int32_t m[16];  // column-major: m[col * 4 + row]
  int frac_bits;       // value = m * 2^-frac_bits, in [0, 60]
};

struct Vec3Q16 {  // a position in Q15.16; w = 1 is implied
  std::int32_t x, y, z;
};

struct Vec4Wide {  // Q31.32: value = component * 2^-32
  std::int64_t x, y, z, w;
};

inline constexpr int vec4_wide_frac_bits = 32;

namespace detail {

// Worst row sum: three products |m| * |coord| <= (2^29 - 1) * 2^31 plus the
// translation |m| * 2^16. It stays below 2^62, so the int64 sum is exact for every
// int32 coordinate (the stated contract, |coords| < 2^30, has 2 bits to spare),
// and adding a rounding half (<= 2^43) cannot overflow either.
inline constexpr std::int64_t max_row_sum =
    3 * (std::int64_t{mat4_block_entry_limit - 1} << 31) + (std::int64_t{mat4_block_entry_limit - 1} << 16);
static_assert(max_row_sum < (std::int64_t{1} << 62));

// x in Q(from_frac) to Q32, rounding ties away from zero. Right shifts are by at
// most 60 + 16 - 32 = 44; left shifts (frac_bits < 16, entries >= 2^13) by at most
// 16, and those saturate to +-INT64_MAX (symmetric, so the result stays odd in x)
// instead of wrapping.
constexpr std::int64_t to_q32(std::int64_t x, int from_frac) {
  if (from_frac >= vec4_wide_frac_bits) {
    const int s = from_frac - vec4_wide_frac_bits;
    const std::uint64_t mag = shr_rounded(magnitude(x), s, rounding::nearest);  // |x| < 2^62: no overflow
    return x < 0 ? -static_cast<std::int64_t>(mag) : static_cast<std::int64_t>(mag);
  }
  const int s = vec4_wide_frac_bits - from_frac;
  const std::int64_t headroom = INT64_MAX >> s;
  if (x > headroom) return INT64_MAX;
  if (x < -headroom) return -INT64_MAX;
  return x * (std::int64_t{1} << s);
}

constexpr std::int64_t transform_row(const Mat4Block& a, int row, const Vec3Q16& v) {
  const std::int32_t* col = a.m;
  // Exact: |sum| <= max_row_sum < 2^62 (see above). Translation: w = 1.0 = 2^16 in Q16.
  // mul_s32_setup: the exact product without libgcc's __muldi3 on ARMv6-M.
  const std::int64_t sum = mul_s32_setup(col[0 + row], v.x) + mul_s32_setup(col[4 + row], v.y) + mul_s32_setup(col[8 + row], v.z) +
                           std::int64_t{col[12 + row]} * 65536;
  return to_q32(sum, a.frac_bits + 16);  // the sum is in Q(frac_bits + 16)
}

}  // namespace detail

// a * (v, 1): each component is the exact sum of int64 products, shifted once to
// Q.32 with rounding to nearest (ties away from zero, so transform(a, -v) mirrors).
// Requires |a.m[i]| < 2^29 and a.frac_bits in [0, 60]; any int32 coordinates.
// A component beyond the Q31.32 range (only possible with frac_bits < 16)
// saturates to +-INT64_MAX.
constexpr Vec4Wide transform(const Mat4Block& a, const Vec3Q16& v) {
  return {detail::transform_row(a, 0, v), detail::transform_row(a, 1, v), detail::transform_row(a, 2, v),
          detail::transform_row(a, 3, v)};
}

// Host-side: quantises a column-major double matrix. frac_bits is the largest in
// [0, 60] with every rounded |entry * 2^frac_bits| < 2^29; entries round to nearest
// (ties away from zero), NaN becomes 0, and values too large even for frac_bits = 0
// saturate to +-(2^29 - 1).
constexpr Mat4Block mat4_block_from_doubles(const double (&col_major)[16]) {
  double max_abs = 0.0;
  for (const double x : col_major) {
    const double a = x < 0 ? -x : x;  // NaN compares false and is skipped
    if (a > max_abs) max_abs = a;
  }
  // round(max_abs * 2^f) < 2^29 exactly when max_abs * 2^f < 2^29 - 0.5 (exact in double).
  constexpr double rounding_limit = static_cast<double>(mat4_block_entry_limit) - 0.5;
  int frac_bits = mat4_block_max_frac_bits;
  double scale = detail::pow2(frac_bits);
  while (frac_bits > 0 && max_abs * scale >= rounding_limit) {
    --frac_bits;
    scale *= 0.5;
  }
  Mat4Block out{};
  out.frac_bits = frac_bits;
  for (int i = 0; i < 16; ++i) {
    // q<29, 0> rounds ties away, maps NaN to 0 and saturates to [-2^29, 2^29 - 1];
    // the clamp below makes the range symmetric, |m| < 2^29.
    const std::int32_t m = q<29, 0>::from_double(col_major[i] * scale).raw();
    out.m[i] = m < -(mat4_block_entry_limit - 1) ? -(mat4_block_entry_limit - 1) : m;
  }
  return out;
}

// Host-side: a position in Q15.16, rounded to nearest and saturating.
constexpr Vec3Q16 vec3_q16(double x, double y, double z) {
  return {q16::from_double(x).raw(), q16::from_double(y).raw(), q16::from_double(z).raw()};
}

// The value of one matrix entry (host-side checks and tools).
constexpr double mat4_block_entry(const Mat4Block& a, int col, int row) {
  return static_cast<double>(a.m[col * 4 + row]) * detail::pow2(-a.frac_bits);
}

}  // namespace fixedpoint
