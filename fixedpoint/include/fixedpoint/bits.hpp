// Bit-level helpers every other header builds on: count-leading-zeros and
// wide products that never overflow. Freestanding: no heap, no exceptions.
#pragma once

#include <cstdint>

namespace fixedpoint {

// Leading zeros of a non-zero value. Cortex-M3/M4/M7 have CLZ; on M0+ the
// compiler calls libgcc's __clzsi2 (a small table walk), still branch-light.
constexpr int clz32(std::uint32_t x) { return __builtin_clz(x); }
constexpr int clz64(std::uint64_t x) { return __builtin_clzll(x); }

// Number of bits needed to hold |x| (0 for 0).
constexpr int bit_length(std::uint64_t x) { return x == 0 ? 0 : 64 - clz64(x); }

// Arithmetic shift right that is also defined for negative values in C++17
// terms (C++20 makes >> on negatives arithmetic; this states the intent).
constexpr std::int64_t asr64(std::int64_t x, int s) { return x >> s; }

// floor(a * b / 2^s) for any int64 a, |b| < 2^31 and 0 <= s <= 32, without
// the 96-bit product overflowing: split a into hi*2^32 + lo (lo unsigned).
// floor((H*2^32 + L) / 2^s) = H*2^(32-s) + floor(L / 2^s) exactly, because
// H*2^32 is a multiple of 2^s. The caller guarantees the result fits int64.
constexpr std::int64_t mul_shift_wide(std::int64_t a, std::int32_t b, int s) {
  const std::int64_t hi = a >> 32;                                         // signed high word
  const std::int64_t lo = static_cast<std::int64_t>(static_cast<std::uint32_t>(a));  // [0, 2^32)
  const std::int64_t high_part = hi * b;  // |hi*b| < 2^62
  const std::int64_t low_part = lo * b;   // |lo*b| < 2^63
  // Add as unsigned (modulo 2^64, converted back exactly in C++20): the sum fits int64, but
  // the high term alone may not (a = INT64_MIN + 1, b = -1, s = 0: it is 2^63), so a signed add could overflow.
  return static_cast<std::int64_t>((static_cast<std::uint64_t>(high_part) << (32 - s)) +
                                   static_cast<std::uint64_t>(low_part >> s));
}

// Clamp an int64 into int32 range: saturation, never wrap.
constexpr std::int32_t saturate32(std::int64_t x) {
  return x > INT32_MAX ? INT32_MAX : (x < INT32_MIN ? INT32_MIN : static_cast<std::int32_t>(x));
}

}  // namespace fixedpoint
