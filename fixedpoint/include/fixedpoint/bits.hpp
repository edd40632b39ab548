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

// 32x32 -> 64-bit products. ARMv6-M (Cortex-M0/M0+) multiplies 32x32 -> 32
// only, so for `int64 * int64` the compiler calls libgcc's __muldi3 (a full
// 64x64 product: about 40 instructions and a call) even when both factors are
// 32-bit. Four 16x16 products inline are about half that. Cores with UMULL /
// SMULL (M3, M4, M7, the host) use the plain product: one instruction.
[[gnu::always_inline]] constexpr std::uint64_t mul_u32_halves(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
  const std::uint32_t ll = al * bl, lh = al * bh, hl = ah * bl, hh = ah * bh;  // each < 2^32
  const std::uint32_t mid = (ll >> 16) + (lh & 0xFFFFu) + (hl & 0xFFFFu);      // < 3 * 2^16
  const std::uint32_t lo = (mid << 16) | (ll & 0xFFFFu);
  const std::uint32_t hi = hh + (lh >> 16) + (hl >> 16) + (mid >> 16);         // the exact top word
  return (std::uint64_t{hi} << 32) | lo;
}

// Two's complement: a = ua - 2^32 [a < 0], so a * b = ua * ub - 2^32 (ub [a < 0] + ua [b < 0])
// modulo 2^64, and the true product fits int64.
[[gnu::always_inline]] constexpr std::int64_t mul_s32_halves(std::int32_t a, std::int32_t b) {
  const auto ua = static_cast<std::uint32_t>(a), ub = static_cast<std::uint32_t>(b);
  const std::uint32_t correction = (a < 0 ? ub : 0u) + (b < 0 ? ua : 0u);  // only its value mod 2^32 matters
  return static_cast<std::int64_t>(mul_u32_halves(ua, ub) - (std::uint64_t{correction} << 32));
}

[[gnu::always_inline]] constexpr std::int64_t mul_s32_u32_halves(std::int32_t a, std::uint32_t b) {
  const auto ua = static_cast<std::uint32_t>(a);
  return static_cast<std::int64_t>(mul_u32_halves(ua, b) - (std::uint64_t{a < 0 ? b : 0u} << 32));
}

#if defined(__ARM_ARCH_6M__)
inline constexpr bool has_long_multiply = false;  // no UMULL/SMULL
#else
inline constexpr bool has_long_multiply = true;
#endif

[[gnu::always_inline]] constexpr std::uint64_t mul_u32(std::uint32_t a, std::uint32_t b) {
  if constexpr (has_long_multiply) return std::uint64_t{a} * b;
  else return mul_u32_halves(a, b);
}
[[gnu::always_inline]] constexpr std::int64_t mul_s32(std::int32_t a, std::int32_t b) {
  if constexpr (has_long_multiply) return std::int64_t{a} * b;
  else return mul_s32_halves(a, b);
}
[[gnu::always_inline]] constexpr std::int64_t mul_s32_u32(std::int32_t a, std::uint32_t b) {
  if constexpr (has_long_multiply) return std::int64_t{a} * b;
  else return mul_s32_u32_halves(a, b);
}

// The same product for code that runs per triangle or per vertex, not per
// pixel: on ARMv6-M one out-of-line copy of the four-product routine (a call
// is cheaper than __muldi3 and the flash is paid once, not at every site).
[[gnu::noinline]] constexpr std::int64_t mul_s32_halves_outlined(std::int32_t a, std::int32_t b) {
  return mul_s32_halves(a, b);
}
[[gnu::always_inline]] constexpr std::int64_t mul_s32_setup(std::int32_t a, std::int32_t b) {
  if constexpr (has_long_multiply) return std::int64_t{a} * b;
  else return mul_s32_halves_outlined(a, b);
}

// a * b for b < 2^16: two 16x16 products on ARMv6-M instead of four.
[[gnu::always_inline]] constexpr std::uint64_t mul_u32_u16(std::uint32_t a, std::uint32_t b) {
  if constexpr (has_long_multiply) return std::uint64_t{a} * b;
  else return (std::uint64_t{(a >> 16) * b} << 16) + (a & 0xFFFFu) * b;  // each product < 2^32
}

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

// 64-bit shifts by an amount known to be below 32, from 32-bit operations: on
// Cortex-M a 64-bit shift by a run-time amount is about a dozen instructions
// (a libgcc call on ARMv6-M) because it must also handle amounts of 32 and more.
// The low word of x >> s, 0 <= s < 32.
constexpr std::uint32_t low_word_shifted_right(std::uint64_t x, int s) {
  const auto lo = static_cast<std::uint32_t>(x), hi = static_cast<std::uint32_t>(x >> 32);
  return (lo >> s) | ((hi << 1) << (31 - s));  // (hi << 1) << (31 - s): hi << (32 - s) without UB at s = 0
}
// x << s as a 64-bit value, 0 <= s < 32.
constexpr std::uint64_t widened_shifted_left(std::uint32_t x, int s) {
  return (std::uint64_t{(x >> 1) >> (31 - s)} << 32) | (x << s);
}

// The high word of x << n, 0 <= n < 64 (with n = clz64(x): x's top 32 significant bits).
constexpr std::uint32_t high_word_shifted_left(std::uint64_t x, int n) {
  const auto lo = static_cast<std::uint32_t>(x), hi = static_cast<std::uint32_t>(x >> 32);
  return n >= 32 ? lo << (n - 32) : (hi << n) | ((lo >> 1) >> (31 - n));
}

// x / 2^s rounded to nearest, ties away from zero (so it is odd in x), for
// 1 <= s <= 62 and |x| < 2^62 (the rounding half cannot overflow).
constexpr std::int64_t shift_right_rounded(std::int64_t x, int s) {
  const std::int64_t half = std::int64_t{1} << (s - 1);
  return x >= 0 ? (x + half) >> s : -((half - x) >> s);
}

// Clamp an int64 into int32 range: saturation, never wrap.
constexpr std::int32_t saturate32(std::int64_t x) {
  return x > INT32_MAX ? INT32_MAX : (x < INT32_MIN ? INT32_MIN : static_cast<std::int32_t>(x));
}

}  // namespace fixedpoint
