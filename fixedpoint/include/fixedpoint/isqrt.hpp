// Integer square root of a 64-bit value, exact: digit by digit (two bits of the
// radicand per step, 32 steps), with additions, shifts and compares only, so it
// is the same instructions' worth on every core and needs no libgcc routine.
#pragma once

#include <cstdint>

namespace fixedpoint {

struct SquareRoot {
  std::uint32_t floor;      // floor(sqrt(x))
  std::uint64_t remainder;  // x - floor^2, in [0, 2 * floor]
};

constexpr SquareRoot isqrt(std::uint64_t x) {
  std::uint64_t remainder = x, root = 0;
  std::uint64_t bit = std::uint64_t{1} << 62;  // the highest power of 4
  while (bit > remainder) bit >>= 2;
  // Invariant (classic restoring method): root holds the digits found so far,
  // scaled so that after the last step root = floor(sqrt(x)) and remainder = x - root^2.
  while (bit != 0) {
    if (remainder >= root + bit) {
      remainder -= root + bit;
      root = (root >> 1) + bit;
    } else {
      root >>= 1;
    }
    bit >>= 2;
  }
  return {static_cast<std::uint32_t>(root), remainder};
}

// sqrt(x) rounded to nearest: floor + 1 exactly when x - floor^2 > floor, because
// (floor + 1/2)^2 = floor^2 + floor + 1/4 and both sides are integers plus the 1/4.
// |result - sqrt(x)| <= 1/2 (a tie is impossible); the result is at most 2^32.
constexpr std::uint64_t isqrt_rounded(std::uint64_t x) {
  const SquareRoot r = isqrt(x);
  return std::uint64_t{r.floor} + (r.remainder > r.floor ? 1u : 0u);
}

}  // namespace fixedpoint
