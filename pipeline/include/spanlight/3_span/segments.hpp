// Stage 3b, how far values may step between exact divides. Along a row, each
// group's value is a ratio of two linear functions of x. Between the span's
// exact ends a and b (RowInterpolation) it is
//
//   f(x) = f_a + F gamma(x),  gamma = (x - a) e_b / den(x),  den(x) = (b - x) e_a + (x - a) e_b,
//
// with F = f_b - f_a and N = b - a, and its derivatives are
//
//   f'(x) = F e_a e_b N / den^2,   f'''(x) = 6 F e_a e_b N (e_b - e_a)^2 / den^4.
//
// A segment of L pixels steps the quadratic through exact points at its start,
// middle and end (forward differences: two adds a pixel), which is within
//
//   |f - q| <= max |f'''| L^3 / 125  <=  |F| e_a e_b N (e_b - e_a)^2 L^3 / (20.8 den_min^4)   (1)
//
// of f (the node polynomial x (x - L/2)(x - L) peaks at L^3 / (12 sqrt 3)),
// den_min the smaller of den(x) and den(x + L). Each segment takes the largest
// power of two L that keeps (1) within 2^-T texel, from logarithms in 1/16 of
// an octave rounded the safe way: one choice per segment, no trials, shifts
// for the steps. The rounded steps drift at most 2^(2k-1) units over 2^k
// pixels, which a second bound keeps below 2^-(T + 1) texel.
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"

namespace spanlight {

// x / 48 for 0 <= x < 2^16 without a divide (M0+ has none): the product stays below 2^32, and
// 43691 / 2^21 exceeds 1/48 by 1 / (3 * 2^21), so x * 43691 / 2^21 stays below x / 48 + 1/48,
// short of the next multiple (span_test checks every x of the range).
constexpr int divide_by_48(int x) { return static_cast<int>((static_cast<std::uint32_t>(x) * 43691u) >> 21); }

// floor(log2 x) for x > 0, from the word that holds the leading one (on ARMv6-M one __clzsi2,
// where a 64-bit count is a __clzdi2 call around it).
constexpr int floor_log2(std::uint64_t x) {
  const auto hi = static_cast<std::uint32_t>(x >> 32);
  return hi != 0 ? 63 - fixedpoint::clz32(hi) : 31 - fixedpoint::clz32(static_cast<std::uint32_t>(x));
}

// log2 in sixteenths of an octave, bounded from below and above: the four bits
// after the leading one pick 16 log2(1 + m/16), rounded down, or 16 log2(1 + (m+1)/16), rounded up.
inline constexpr std::uint8_t log2_16_floor_table[16] = {0, 1, 2, 3, 5, 6, 7, 8, 9, 10, 11, 12, 12, 13, 14, 15};
inline constexpr std::uint8_t log2_16_ceil_table[16] = {2, 3, 4, 6, 7, 8, 9, 10, 11, 12, 13, 13, 14, 15, 16, 16};
constexpr unsigned top_four_bits_after_leading_one(std::uint64_t x, int e) {
  return (e >= 4 ? fixedpoint::word_shifted_right(x, e - 4) : static_cast<std::uint32_t>(x) << (4 - e)) & 15u;
}
constexpr int log2_16_down(std::uint64_t x) {
  const int e = floor_log2(x);
  return 16 * e + log2_16_floor_table[top_four_bits_after_leading_one(x, e)];
}
constexpr int log2_16_up(std::uint64_t x) {
  const int e = floor_log2(x);
  const bool power_of_two = (x & (x - 1)) == 0;  // log2 exact
  return 16 * e + (power_of_two ? 0 : log2_16_ceil_table[top_four_bits_after_leading_one(x, e)]);
}

// The segment lengths of one group along one span.
struct SegmentPlanner {
  std::int32_t a, b;       // the span's ends
  std::uint32_t e_a, e_b;  // RowInterpolation's divisors at a and b (< 2^31)
  int fixed_log2;          // >= 0: every segment this long (nothing to bound: f or den constant)
  int accuracy16;          // (1) in 16 log2: 3 log2 L <= (4 log2 den_min - accuracy) / 16
  int max_log2;            // the knob, and the rounding bound

  // F in texels with 8 fraction bits; texel_bits: log2 of step units per texel;
  // tolerance 2^-tolerance_log2 texel (0: accuracy unbounded).
  constexpr void start(std::int32_t column_a, std::int32_t column_b, std::uint32_t divisor_a, std::uint32_t divisor_b,
                       std::uint64_t delta_texels8, int texel_bits, int tolerance_log2, int max_length_log2) {
    a = column_a;
    b = column_b;
    e_a = divisor_a;
    e_b = divisor_b;
    // Rounding: 2^(2k-1) units <= 2^-(T+1) texel, 2k <= texel_bits - T.
    const int rounding_log2 = (texel_bits - (tolerance_log2 > 0 ? tolerance_log2 : 3)) >> 1;
    max_log2 = rounding_log2 < max_length_log2 ? (rounding_log2 > 0 ? rounding_log2 : 0) : max_length_log2;
    fixed_log2 = -1;
    if (delta_texels8 == 0 || e_a == e_b || e_a == 0 || e_b == 0) {
      fixed_log2 = max_log2;
      return;
    }
    const std::uint32_t de = e_a > e_b ? e_a - e_b : e_b - e_a;
    const int slope16 = log2_16_up(delta_texels8) - 16 * 8 + log2_16_up(static_cast<std::uint64_t>(b - a)) +
                        log2_16_up(e_a) + log2_16_up(e_b);  // 16 log2 of |F| e_a e_b N
    // log2 20.8 > 4: 3 log2 L <= 4 - T + 4 log2 den_min - log2 (|F| e_a e_b N) - 2 log2 |e_b - e_a|
    accuracy16 = tolerance_log2 == 0 ? -(1 << 20) : slope16 + 2 * log2_16_up(de) + 16 * (tolerance_log2 - 4);
  }

  constexpr std::uint64_t den(std::int32_t x) const {
    return fixedpoint::mul_u32_u16(e_a, static_cast<std::uint32_t>(b - x)) + fixedpoint::mul_u32_u16(e_b, static_cast<std::uint32_t>(x - a));
  }
  constexpr int log2_for(std::uint64_t den_min) const {
    // k = floor(x / 48) clamped to [0, max_log2]: the clamps need no quotient, and between them
    // x < 48 (max_log2 + 1) <= 48 * 64 is within divide_by_48's range (max_log2 is at most the
    // span knob's log2, 6).
    const int x = 4 * log2_16_down(den_min) - accuracy16;
    if (x < 48) return 0;
    if (x >= 48 * (max_log2 + 1)) return max_log2;
    return divide_by_48(x);
  }

  // log2 of the segment that starts at column x.
  constexpr int length_log2_at(std::int32_t x) const { return fixed_log2 >= 0 ? fixed_log2 : length_log2_at(x, den(x)); }
  // The same where den(x) is known: RowInterpolation::at's denominator at x is den(x), the same two products.
  constexpr int length_log2_at(std::int32_t x, std::uint64_t den_x) const {
    if (fixed_log2 >= 0) return fixed_log2;
    int k = log2_for(den_x);
    if (e_a > e_b && k > 0) {  // den falls along the row: den_min is at the segment's end
      const std::int32_t end = x + (std::int32_t{1} << k) < b ? x + (std::int32_t{1} << k) : b;
      const int at_end = log2_for(den(end));
      if (at_end < k) k = at_end;  // den(x + L') >= den(end) for the shorter L': still within
    }
    return k;
  }
};

// The forward differences of the quadratic through f0, f0 + d1, f0 + d1 + d2 at
// pixels 0, 2^(k-1) and 2^k (k >= 1; d1, d2 exact differences, |d| < 2^30), in
// units 2^shift times finer (shift <= 20): q(j + 1) - q(j) = step + j * curve,
// modulo 2^32 (a repeating texture's coordinate wraps as the texture does).
struct QuadraticSteps {
  std::uint32_t step, curve;
};
constexpr QuadraticSteps quadratic_steps(std::int32_t d1, std::int32_t d2, int k, int shift) {
  // q(j) = f0 + j d1 / h + j (j - h) c, h = 2^(k-1), c = (d2 - d1) / 2^(2k-1):
  // curve = 2c = (d2 - d1) / 2^(2k-2), step = d1 / h + c (1 - h) = (2^k d1 + (d2 - d1)(1 - h)) / 2^(2k-1).
  const int s = 2 * k - 1;
  if (shift >= s) {
    // Enough finer units to hold both exactly: shifts left, and modulo 2^32 is the answer.
    const auto dd = static_cast<std::uint32_t>(d2) - static_cast<std::uint32_t>(d1);
    const std::uint32_t step_num = (static_cast<std::uint32_t>(d1) << k) + dd * (1u - (1u << (k - 1)));
    return {step_num << (shift - s), dd << (shift - s + 1)};
  }
  // Else divided by 2^(s - shift), rounded to nearest, in 64 bits (|numerators| < 2^(31 + k + 1) <= 2^38),
  // from 32-bit pieces: |d2 - d1| < 2^31 fits a word, d1 2^k is d1's word shifted into two, the
  // product is one mul_s32, and the shifts (right <= 2k - 1 <= 11) keep one word of the result:
  // on ARMv6-M no libgcc shift or multiply.
  const auto dd = static_cast<std::int32_t>(std::int64_t{d2} - d1);
  const std::int64_t step_num = fixedpoint::widened_shifted_left(d1, k) + fixedpoint::mul_s32(dd, 1 - (std::int32_t{1} << (k - 1)));  // 1 <= k < 32
  const int right = s - shift;  // >= 1
  const std::uint32_t step = fixedpoint::low_word_shifted_right(static_cast<std::uint64_t>(step_num + (std::int32_t{1} << (right - 1))), right);
  const std::uint32_t curve =
      right == 1 ? static_cast<std::uint32_t>(dd)
                 : static_cast<std::uint32_t>(fixedpoint::floor_shifted_right(std::int64_t{dd} + (std::int32_t{1} << (right - 2)), right - 1));
  return {step, curve};
}

}  // namespace spanlight
