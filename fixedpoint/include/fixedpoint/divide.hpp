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

// n / d rounded to nearest, ties away from zero, for d > 0 and |n| < d * 2^32.
constexpr std::int64_t divide_rounded(std::int64_t n, std::uint32_t d) {
  const std::uint64_t magnitude = n < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(n) : static_cast<std::uint64_t>(n);
  const DivMod qr = div_mod(magnitude, d);
  // remainder >= d/2 exactly when remainder >= d - remainder (no overflow: remainder < d).
  const std::int64_t rounded = std::int64_t{qr.quotient} + (qr.remainder >= d - qr.remainder ? 1 : 0);
  return n < 0 ? -rounded : rounded;
}

}  // namespace fixedpoint
