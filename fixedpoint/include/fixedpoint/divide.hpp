// Exact integer division without a divide instruction or libgcc's division
// routines (Cortex-M0+ has neither UDIV nor a 64-bit divide): a reciprocal
// estimate from reciprocal.hpp, then a short exact correction by remainder.
//
// The estimate q0 = floor(n_top * y / 2^k) uses y = reciprocal<8, 2>(d), which is
// never above 1/d (docs/reciprocal.md: after a Newton step the error is one-sided),
// and n_top, the top 32 significant bits of n (truncated). So q0 <= n/d, and
//     n/d - q0 < (n/d) * (1.88e-9 + 2^-31) + 1 < 2^32 * 2.35e-9 + 1 < 11.1,
// for quotients below 2^32: at most 11 correction steps, each one compare and one subtract.
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/reciprocal.hpp"

namespace fixedpoint {

struct DivMod {
  std::uint32_t quotient;
  std::uint32_t remainder;  // n = quotient * d + remainder, remainder < d
};

// floor(n / d) and the remainder, for d > 0 and n / d < 2^32 (n < d * 2^32).
constexpr DivMod div_mod(std::uint64_t n, std::uint32_t d) {
  if (n == 0) return {0, 0};
  const Reciprocal y = reciprocal<8, 2>(d);                // 1/d >= y.mantissa * 2^-y.shift
  const int leading = clz64(n);
  const std::uint32_t n_top = high_word_shifted_left(n, leading);  // n >= n_top * 2^(32 - leading)
  // n/d >= n_top * mantissa * 2^(32 - leading - shift). shift >= 31, so the exponent is
  // at most 1, and it is >= 0 only for n >= 2^62.
  const std::uint64_t product = mul_u32(n_top, y.mantissa);  // < 2^63
  const int exponent = 32 - leading - y.shift;
  std::uint64_t q = 0;
  if (exponent >= 0) {
    q = product << exponent;  // product < 2^63, so no bit is lost
  } else if (exponent > -64) {
    q = product >> -exponent;
  }
  // q <= floor(n / d) < 2^32, so q * d <= n: the remainder is non-negative and exact.
  auto quotient = static_cast<std::uint32_t>(q);
  std::uint64_t remainder = n - mul_u32(quotient, d);
  while (remainder >= d) {  // at most 11 times (see above)
    remainder -= d;
    ++quotient;
  }
  return {quotient, static_cast<std::uint32_t>(remainder)};
}

// floor(n / d) and n - floor(n / d) * d in [0, d), for any n > INT64_MIN and 0 < d < 2^32,
// by two steps of long division with div_mod: the high word's remainder is below d, so the
// second step's quotient is below 2^32 as div_mod requires. No 64-bit divide (on Cortex-M
// that is a libgcc call, and M0+ has no divide at all).
struct WideFloorDivMod {
  std::int64_t quotient;
  std::uint32_t remainder;
};
constexpr WideFloorDivMod floor_div_wide(std::int64_t n, std::uint32_t d) {
  const std::uint64_t magnitude = n < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(n) : static_cast<std::uint64_t>(n);
  const DivMod high = div_mod(magnitude >> 32, d);
  const DivMod low = div_mod((std::uint64_t{high.remainder} << 32) | (magnitude & 0xFFFFFFFFu), d);
  const auto q = static_cast<std::int64_t>((std::uint64_t{high.quotient} << 32) | low.quotient);  // <= |n| < 2^63
  if (n >= 0) return {q, low.remainder};
  if (low.remainder == 0) return {-q, 0};
  return {-q - 1, d - low.remainder};
}

// n / d rounded to nearest, ties away from zero, for d > 0 and |n| < d * 2^32.
constexpr std::int64_t divide_rounded(std::int64_t n, std::uint32_t d) {
  const std::uint64_t magnitude = n < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(n) : static_cast<std::uint64_t>(n);
  const DivMod qr = div_mod(magnitude, d);
  // remainder >= d/2 exactly when remainder >= d - remainder (no overflow: remainder < d).
  const std::int64_t rounded = std::int64_t{qr.quotient} + (qr.remainder >= d - qr.remainder ? 1 : 0);
  return n < 0 ? -rounded : rounded;
}

}  // namespace fixedpoint

namespace fixedpoint {

// Floor division of 32-bit values by one divisor, many times: with the core's
// divide instruction where it has one (Cortex-M3/M4/M7, the host), else by the
// divisor's reciprocal and an exact correction (Cortex-M0+: no libgcc call).
// Either way the exact floor(n / d) and n - floor(n / d) * d in [0, d).
#if defined(__arm__) && !defined(__ARM_FEATURE_IDIV)
inline constexpr bool has_divide_instruction = false;
#else
inline constexpr bool has_divide_instruction = true;
#endif

struct FloorDivisor {
  std::uint32_t d;  // in (0, 2^31)
  Reciprocal y;     // 1/d from below (reciprocal<8, 2>: relative error < 2^-28.9), without a divide instruction

  constexpr explicit FloorDivisor(std::uint32_t divisor) : d(divisor), y{} {
    if constexpr (!has_divide_instruction) y = reciprocal<8, 2>(divisor);
  }

  // |n| / d, exactly: q0 = floor(|n| y) <= |n| / d and |n| / d - q0 < 2^31 * 2^-28.9 + 1 < 6.
  [[gnu::always_inline]] constexpr std::uint32_t unsigned_quotient(std::uint32_t n) const {
    if constexpr (has_divide_instruction) return n / d;
    else return quotient_by_reciprocal(n, d, y);
  }

  // The same from the reciprocal y of d (the path without a divide instruction; a function of
  // its own so that the host's tests run it too).
  [[gnu::always_inline]] static constexpr std::uint32_t quotient_by_reciprocal(std::uint32_t n, std::uint32_t d, Reciprocal y) {
    auto q = word_shifted_right(mul_u32(n, y.mantissa), y.shift);  // y.shift in [31, 62] for d < 2^31
    std::uint32_t r = n - q * d;
    while (r >= d) {
      r -= d;
      ++q;
    }
    return q;
  }

  struct Result {
    std::int32_t quotient, remainder;
  };
  constexpr Result floor_div(std::int32_t n) const {
    const std::uint32_t magnitude = n < 0 ? 0u - static_cast<std::uint32_t>(n) : static_cast<std::uint32_t>(n);
    const std::uint32_t q = unsigned_quotient(magnitude);
    const std::uint32_t r = magnitude - q * d;
    if (n >= 0) return {static_cast<std::int32_t>(q), static_cast<std::int32_t>(r)};
    if (r == 0) return {-static_cast<std::int32_t>(q), 0};
    return {-static_cast<std::int32_t>(q) - 1, static_cast<std::int32_t>(d - r)};
  }
};

}  // namespace fixedpoint
