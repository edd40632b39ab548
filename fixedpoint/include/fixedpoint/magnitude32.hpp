// A positive value as a 32-bit normalised mantissa and a binary exponent, for
// the few products and quotients of the pose builders that span too many
// octaves for one fixed format (cot(fovy/2) runs from 2^-14 to 2^14). Integers
// only; every operation rounds once, to a relative error of at most 2^-32
// (half a unit in the 32nd bit of a mantissa >= 2^31), except quotient().
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/mat4.hpp"
#include "fixedpoint/reciprocal.hpp"

namespace fixedpoint {

struct Magnitude32 {
  std::uint32_t mantissa;  // in [2^31, 2^32)
  int exponent;            // value = mantissa * 2^exponent
};

// x * 2^exponent for x > 0, rounded to 32 significant bits (exact when x < 2^32).
constexpr Magnitude32 magnitude32(std::uint64_t x, int exponent) {
  const int excess = bit_length(x) - 32;
  if (excess <= 0) return {static_cast<std::uint32_t>(x << -excess), exponent + excess};
  const std::uint64_t rounded = ((x >> (excess - 1)) + 1) >> 1;  // half up
  if (rounded >> 32) return {0x80000000u, exponent + excess + 1};  // carried into bit 32: exactly 2^32
  return {static_cast<std::uint32_t>(rounded), exponent + excess};
}

constexpr Magnitude32 operator*(const Magnitude32& a, const Magnitude32& b) {
  return magnitude32(mul_u32(a.mantissa, b.mantissa), a.exponent + b.exponent);
}

// num / den as an exact Scaled (num's mantissa times the reciprocal's), negated if asked:
// its relative error is the reciprocal's, <= 1.878e-9 for reciprocal<8, 2> (docs/reciprocal.md).
constexpr Scaled quotient(const Magnitude32& num, const Magnitude32& den, bool negative) {
  const Reciprocal y = reciprocal<8, 2>(den.mantissa);  // 1/den.mantissa ~= y.mantissa * 2^-y.shift
  const auto product = static_cast<std::int64_t>(mul_u32(num.mantissa, y.mantissa));  // < 2^63
  return {negative ? -product : product, y.shift + den.exponent - num.exponent};
}

}  // namespace fixedpoint
