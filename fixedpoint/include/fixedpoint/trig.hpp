// Angles as a fraction of a turn, and their sine and cosine, in integers only.
//
// Turns: raw / 2^32 of a full turn, so angles wrap exactly as uint32 does (an
// orbit never drifts) and the octant is the top three bits. 1 degree is about
// 11930465 raw; the step is 8.4e-8 degrees.
//
// Both sine/cosine and the perspective's cotangent reduce their angle to
// z in [0, pi/4] and evaluate two Taylor polynomials in w = z^2 <= 0.617:
//     sin z = z * S(w),  S(w) = sum_{k=0..5} (-w)^k / (2k+1)!
//     cos z =     C(w),  C(w) = sum_{k=0..6} (-w)^k / (2k)!
// Alternating series with decreasing terms: the truncation is below the first
// omitted term, w^6/13! < 2^-36.6 for S and w^7/14! < 2^-41.2 for C. Horner runs
// in Q.60 (int64): each step floors once (2^-60) and each coefficient is rounded
// (2^-61), so the arithmetic adds less than 2^-56 to either polynomial.
// Both bounds hold for the w the kernels are given; the error of w itself (from
// rounding z) is accounted where z is made (reduced_angle).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "fixedpoint/bits.hpp"

namespace fixedpoint {

struct Turns {
  std::uint32_t raw;  // angle = raw / 2^32 turn
  friend constexpr bool operator==(Turns, Turns) = default;
};

inline constexpr double turns_raw_per_degree = 4294967296.0 / 360.0;

// Host side, or constant expressions on the target (a run-time call would need floating point).
// Rounded to nearest and wrapped into [0, 1) turn, for |degrees| < 1e15; NaN and larger give 0.
constexpr Turns turns_from_degrees(double degrees) {
  if (!(degrees > -1e15 && degrees < 1e15)) return {0};  // keeps the conversion to int64 below defined
  double raw = degrees * turns_raw_per_degree;
  const double turn = 4294967296.0;
  raw -= static_cast<double>(static_cast<std::int64_t>(raw / turn)) * turn;  // now in (-2^32, 2^32)
  if (raw < 0) raw += turn;
  const auto rounded = static_cast<std::uint64_t>(raw + 0.5);
  return {static_cast<std::uint32_t>(rounded)};  // 2^32 wraps to 0
}

// Exact: raw * 360 < 2^41 and the division is by a power of two.
constexpr double degrees(Turns a) { return static_cast<double>(a.raw) * 360.0 / 4294967296.0; }

struct SinCos {
  std::int32_t sin, cos;  // Q1.30
};

namespace detail {

inline constexpr int poly_frac_bits = 60;
inline constexpr double sin_over_z_kernel_error = 1.1e-11;  // 2^-36.6 + 2^-56
inline constexpr double cos_kernel_error = 4.0e-13;         // 2^-41.2 + 2^-56

// round(2^60 / n!) with alternating signs, highest power first (Horner order).
template <std::size_t Terms>
constexpr std::array<std::int64_t, Terms> taylor_q60(int first_factorial) {
  std::array<std::int64_t, Terms> c{};
  for (std::size_t k = 0; k < Terms; ++k) {
    const int n = first_factorial + 2 * static_cast<int>(k);
    std::uint64_t factorial = 1;
    for (int i = 2; i <= n; ++i) factorial *= static_cast<std::uint64_t>(i);  // 14! < 2^37
    const std::uint64_t magnitude = ((std::uint64_t{1} << poly_frac_bits) + factorial / 2) / factorial;
    c[Terms - 1 - k] = (k % 2 == 0) ? static_cast<std::int64_t>(magnitude) : -static_cast<std::int64_t>(magnitude);
  }
  return c;
}

inline constexpr std::array<std::int64_t, 6> sin_over_z_coefficients = taylor_q60<6>(1);  // 1/1!, -1/3!, ... -1/11!
inline constexpr std::array<std::int64_t, 7> cos_coefficients = taylor_q60<7>(0);          // 1/0!, -1/2!, ... 1/12!

// Horner in Q.60 with w in Q0.31 (w < 2^31): acc * w / 2^31 floors, |acc| <= 1 keeps it exact in int64.
template <std::size_t N>
constexpr std::int64_t horner_q60(const std::array<std::int64_t, N>& c, std::int32_t w_q31) {
  std::int64_t acc = c[0];
  for (std::size_t i = 1; i < N; ++i) acc = c[i] + mul_shift_wide(acc, w_q31, 31);
  return acc;
}

// z = h * pi / 2^32 radians for h in [0, 2^30] (z in [0, pi/4]); h counts 2^-33 turn.
// K = round(pi * 2^30) is off by a relative 3.7e-11 (< 2^-34.6).
inline constexpr std::uint32_t pi_q30 = 3373259426u;

struct ReducedAngle {
  std::uint64_t z_q62;   // z * 2^62 = h * K, exact given K: < 2^61.7
  std::uint32_t z_q32;   // z in Q0.32, rounded: |error| <= 2^-33 + z * 2^-34.6
  std::int32_t w_q31;    // z^2 in Q0.31, rounded: |error| <= 2z |z error| + 2^-32 < 1.94 * 2^-32
};

constexpr ReducedAngle reduced_angle(std::uint32_t h) {
  const std::uint64_t z_q62 = mul_u32(h, pi_q30);
  const auto z_q32 = static_cast<std::uint32_t>((z_q62 + (std::uint64_t{1} << 29)) >> 30);  // < pi/4 * 2^32 < 2^32
  const std::uint64_t z2_q64 = mul_u32(z_q32, z_q32);
  const auto w_q31 = static_cast<std::int32_t>((z2_q64 + (std::uint64_t{1} << 32)) >> 33);  // < 0.617 * 2^31
  return {z_q62, z_q32, w_q31};
}

// sin(z)/z and cos(z), Q.60, for w = z^2 in Q0.31. Values: S in [0.90, 1], C in [0.707, 1].
// Error: the truncation and arithmetic above, plus the effect of w's error
// (|S'| <= 1/6, |C'| <= 1/2): |S error| < 2^-33.4, |C error| < 2^-32.
constexpr std::int64_t sin_over_z_q60(std::int32_t w_q31) { return horner_q60(sin_over_z_coefficients, w_q31); }
constexpr std::int64_t cos_q60(std::int32_t w_q31) { return horner_q60(cos_coefficients, w_q31); }

}  // namespace detail

// sin and cos of a in Q1.30, each within 0.93 * 2^-30 of the exact value. In units of 2^-31:
// sin = z32 * S31 rounded to Q1.30: z32's error 0.25 + 0.07, S31's rounding times z 0.39,
// S's error times z 0.15, the final rounding 1: 1.86; cos = C rounded: 1 + C's error 0.5.
inline constexpr double sin_cos_error = 0.93;  // units of 2^-30
constexpr SinCos sin_cos(Turns a) {
  const std::uint32_t quadrant = a.raw >> 30;
  const std::uint32_t within = a.raw & ((1u << 30) - 1);  // 2^-32 turn units, < 1/4 turn
  // Reduce to [0, 1/8 turn]: past the octant, use the complement and swap sin and cos.
  const bool complement = within > (1u << 29);
  const std::uint32_t g = complement ? (1u << 30) - within : within;  // <= 2^29
  const detail::ReducedAngle r = detail::reduced_angle(2 * g);
  const std::int64_t s_q60 = detail::sin_over_z_q60(r.w_q31);
  const std::int64_t c_q60 = detail::cos_q60(r.w_q31);
  // S in Q1.31 fits uint32 (S <= 1); z32 * S31 is Q1.63, rounded to Q1.30.
  const auto s_q31 = static_cast<std::uint32_t>((s_q60 + (std::int64_t{1} << 28)) >> 29);
  const auto sin_z = static_cast<std::int32_t>((mul_u32(r.z_q32, s_q31) + (std::uint64_t{1} << 32)) >> 33);
  const auto cos_z = static_cast<std::int32_t>((c_q60 + (std::int64_t{1} << 29)) >> 30);
  const std::int32_t s = complement ? cos_z : sin_z;  // sin and cos of the angle within the quadrant
  const std::int32_t c = complement ? sin_z : cos_z;
  switch (quadrant) {
    case 0: return {s, c};
    case 1: return {c, -s};
    case 2: return {-s, -c};
    default: return {-c, s};
  }
}

}  // namespace fixedpoint
