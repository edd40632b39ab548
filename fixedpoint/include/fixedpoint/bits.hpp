// Bit-level helpers every other header builds on: count-leading-zeros and
// wide products that never overflow. Freestanding: no heap, no exceptions.
#pragma once

#include <cstdint>
#include <type_traits>

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
// modulo 2^64, and the true product fits int64. Only the correction's value mod 2^32 matters.
[[gnu::always_inline]] constexpr std::uint32_t sign_correction(std::int32_t a, std::int32_t b) {
  return (a < 0 ? static_cast<std::uint32_t>(b) : 0u) + (b < 0 ? static_cast<std::uint32_t>(a) : 0u);
}
// The correction touches the high word only: subtracted there, the low word is left as it is
// (written word by word, so ARMv6-M code does no 64-bit subtraction).
[[gnu::always_inline]] constexpr std::int64_t signed_from_unsigned(std::uint64_t unsigned_product, std::uint32_t correction) {
  const auto lo = static_cast<std::uint32_t>(unsigned_product), hi = static_cast<std::uint32_t>(unsigned_product >> 32) - correction;
  return static_cast<std::int64_t>((std::uint64_t{hi} << 32) | lo);
}

[[gnu::always_inline]] constexpr std::int64_t mul_s32_halves(std::int32_t a, std::int32_t b) {
  return signed_from_unsigned(mul_u32_halves(static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)), sign_correction(a, b));
}

[[gnu::always_inline]] constexpr std::int64_t mul_s32_u32_halves(std::int32_t a, std::uint32_t b) {
  return signed_from_unsigned(mul_u32_halves(static_cast<std::uint32_t>(a), b), a < 0 ? b : 0u);
}

#if defined(__ARM_ARCH_6M__)
inline constexpr bool has_long_multiply = false;  // no UMULL/SMULL
#else
inline constexpr bool has_long_multiply = true;
#endif

#if defined(__ARM_ARCH_6M__)
// mul_u32_halves in Thumb-1, inline: five registers, the middle sum's carry through ADCS (GCC's
// schedule of the C above keeps more values alive and spills in the loops that call it).
[[gnu::always_inline]] inline std::uint64_t mul_u32_thumb1(std::uint32_t a, std::uint32_t b) {
  std::uint32_t al, bl, lo;
  __asm__(
      ".syntax unified\n\t"  // GCC hands Thumb-1 inline assembly over in divided syntax
      "uxth  %[al], %[a]\n\t"
      "lsrs  %[a], %[a], #16\n\t"
      "uxth  %[bl], %[b]\n\t"
      "lsrs  %[b], %[b], #16\n\t"
      "movs  %[lo], %[al]\n\t"
      "muls  %[lo], %[bl], %[lo]\n\t"  // ll
      "muls  %[al], %[b], %[al]\n\t"   // lh
      "muls  %[bl], %[a], %[bl]\n\t"   // hl
      "muls  %[a], %[b], %[a]\n\t"     // hh
      "movs  %[b], #0\n\t"
      "adds  %[al], %[al], %[bl]\n\t"  // mid, its carry out
      "adcs  %[b], %[b]\n\t"
      "lsls  %[b], %[b], #16\n\t"
      "adds  %[a], %[a], %[b]\n\t"
      "lsls  %[bl], %[al], #16\n\t"
      "lsrs  %[al], %[al], #16\n\t"
      "adds  %[lo], %[lo], %[bl]\n\t"
      "adcs  %[a], %[al]\n\t"
      ".syntax divided\n\t"
      : [a] "+l"(a), [b] "+l"(b), [al] "=&l"(al), [bl] "=&l"(bl), [lo] "=&l"(lo)
      :
      : "cc");
  return (std::uint64_t{a} << 32) | lo;
}
#endif

[[gnu::always_inline]] constexpr std::uint64_t mul_u32(std::uint32_t a, std::uint32_t b) {
  if constexpr (has_long_multiply) {
    return std::uint64_t{a} * b;
  } else {
#if defined(__ARM_ARCH_6M__)
    if (!std::is_constant_evaluated()) return mul_u32_thumb1(a, b);
#endif
    return mul_u32_halves(a, b);
  }
}
[[gnu::always_inline]] constexpr std::int64_t mul_s32(std::int32_t a, std::int32_t b) {
  if constexpr (has_long_multiply) {
    return std::int64_t{a} * b;
  } else {
    return signed_from_unsigned(mul_u32(static_cast<std::uint32_t>(a), static_cast<std::uint32_t>(b)), sign_correction(a, b));
  }
}
[[gnu::always_inline]] constexpr std::int64_t mul_s32_u32(std::int32_t a, std::uint32_t b) {
  if constexpr (has_long_multiply) {
    return std::int64_t{a} * b;
  } else {
    return signed_from_unsigned(mul_u32(static_cast<std::uint32_t>(a), b), a < 0 ? b : 0u);
  }
}
// a b for b >= 0: the signed multiply where there is one (smull; mul_s32_u32's form costs a
// correction there), else mul_s32_u32, one sign correction fewer than mul_s32.
[[gnu::always_inline]] constexpr std::int64_t mul_s32_nonnegative(std::int32_t a, std::int32_t b) {
  if constexpr (has_long_multiply) {
    return std::int64_t{a} * b;
  } else {
    return mul_s32_u32(a, static_cast<std::uint32_t>(b));
  }
}

// The same product for code that runs per triangle or per vertex, not per
// pixel: on ARMv6-M one out-of-line copy of the four-product routine (a call
// is cheaper than __muldi3 and the flash is paid once, not at every site).
#if defined(__ARM_ARCH_6M__)
// Written out in Thumb-1: GCC schedules mul_s32_halves into a stack frame with
// spills (37 instructions); here the middle sum's carry goes through ADCS and
// nothing leaves the registers (24 instructions and the push and pop). The same
// value as mul_s32_halves: ua ub = hh 2^32 + (lh + hl) 2^16 + ll, minus the
// two's complement correction in the high word.
[[gnu::noinline]] inline std::int64_t mul_s32_thumb1(std::int32_t a, std::int32_t b) {
  auto lo = static_cast<std::uint32_t>(a), hi = static_cast<std::uint32_t>(b);
  std::uint32_t al, ah, bl, bh, correction;
  __asm__(
      ".syntax unified\n\t"  // GCC hands Thumb-1 inline assembly over in divided syntax
      "uxth  %[al], %[lo]\n\t"
      "lsrs  %[ah], %[lo], #16\n\t"
      "uxth  %[bl], %[hi]\n\t"
      "lsrs  %[bh], %[hi], #16\n\t"
      "asrs  %[corr], %[lo], #31\n\t"
      "ands  %[corr], %[hi]\n\t"         // b if a < 0
      "asrs  %[hi], %[hi], #31\n\t"
      "ands  %[hi], %[lo]\n\t"           // a if b < 0
      "adds  %[corr], %[corr], %[hi]\n\t"
      "movs  %[lo], %[al]\n\t"
      "muls  %[lo], %[bl], %[lo]\n\t"    // ll = al bl
      "muls  %[al], %[bh], %[al]\n\t"    // lh = al bh
      "muls  %[bl], %[ah], %[bl]\n\t"    // hl = ah bl
      "muls  %[ah], %[bh], %[ah]\n\t"    // hh = ah bh
      "movs  %[bh], #0\n\t"
      "adds  %[al], %[al], %[bl]\n\t"    // mid = lh + hl, its carry out
      "adcs  %[bh], %[bh]\n\t"           // the carry, worth 2^48
      "lsls  %[bh], %[bh], #16\n\t"
      "adds  %[ah], %[ah], %[bh]\n\t"
      "lsls  %[bl], %[al], #16\n\t"
      "lsrs  %[al], %[al], #16\n\t"
      "adds  %[lo], %[lo], %[bl]\n\t"    // lo = ll + (mid << 16), its carry out
      "adcs  %[ah], %[al]\n\t"           // hi = hh + (mid >> 16) + the carries
      "subs  %[hi], %[ah], %[corr]\n\t"  // signed: minus the correction
      ".syntax divided\n\t"
      : [lo] "+l"(lo), [hi] "+l"(hi), [al] "=&l"(al), [ah] "=&l"(ah), [bl] "=&l"(bl), [bh] "=&l"(bh),
        [corr] "=&l"(correction)
      :
      : "cc");
  return static_cast<std::int64_t>((std::uint64_t{hi} << 32) | lo);
}
#endif
[[gnu::always_inline]] constexpr std::int64_t mul_s32_setup(std::int32_t a, std::int32_t b) {
  if constexpr (has_long_multiply) {
    return std::int64_t{a} * b;
  } else {
#if defined(__ARM_ARCH_6M__)
    if (!std::is_constant_evaluated()) return mul_s32_thumb1(a, b);
#endif
    return mul_s32_halves(a, b);  // reached in constant evaluation only
  }
}

// a * b for b < 2^16: two 16x16 products on ARMv6-M instead of four.
[[gnu::always_inline]] constexpr std::uint64_t mul_u32_u16(std::uint32_t a, std::uint32_t b) {
  if constexpr (has_long_multiply) return std::uint64_t{a} * b;
  else return (std::uint64_t{(a >> 16) * b} << 16) + (a & 0xFFFFu) * b;  // each product < 2^32
}

// floor(x n / 2^s) for 0 <= x <= 2^28, 0 <= n < 2^13 and 12 <= s < 32: a Q.28 fraction of a
// size with 28 - s fraction bits kept (a texel coordinate in a projector's image or shadow map),
// the product below 2^41. Without a long multiply, two 32-bit products: x = a 2^12 + b (a <= 2^16,
// b < 2^12) and a n is an integer, so floor((a n 2^12 + b n) / 2^s) =
// floor((a n + floor(b n / 2^12)) / 2^(s - 12)), with a n < 2^29 and b n < 2^25.
[[gnu::always_inline]] constexpr std::int32_t mul_u28_u13_split(std::int32_t x, std::int32_t n, int s) {
  const auto ux = static_cast<std::uint32_t>(x), un = static_cast<std::uint32_t>(n);
  return static_cast<std::int32_t>(((ux >> 12) * un + (((ux & 0xFFFu) * un) >> 12)) >> (s - 12));
}
[[gnu::always_inline]] constexpr std::int32_t mul_u28_u13_shifted(std::int32_t x, std::int32_t n, int s) {
  if constexpr (has_long_multiply) {
    return static_cast<std::int32_t>(std::uint64_t{static_cast<std::uint32_t>(x)} * static_cast<std::uint32_t>(n) >> s);
  } else {
    return mul_u28_u13_split(x, n, s);
  }
}

// round(a b / 2^32), halves up, for a < 2^25 and b < 2^24 (the product below 2^49). Without a
// long multiply, four 16 x 16 products and no carries: with a = ah 2^16 + al, b = bh 2^16 + bl,
// a b + 2^31 = ah bh 2^32 + (ah bl + al bh + 2^15) 2^16 + al bl, and the low 16 bits of al bl
// cannot reach the next multiple of 2^16, so the result is
// ah bh + floor((ah bl + al bh + 2^15 + floor(al bl / 2^16)) / 2^16); ah bl < 2^25, al bh < 2^24,
// the sum below 2^26.
[[gnu::always_inline]] constexpr std::uint32_t mul_u25_u24_rounded_high_split(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t al = a & 0xFFFFu, ah = a >> 16, bl = b & 0xFFFFu, bh = b >> 16;
  return ah * bh + ((ah * bl + al * bh + 0x8000u + ((al * bl) >> 16)) >> 16);
}
[[gnu::always_inline]] constexpr std::uint32_t mul_u25_u24_rounded_high(std::uint32_t a, std::uint32_t b) {
  if constexpr (has_long_multiply) {
#if defined(__arm__)
    // One UMLAL onto the rounding half (GCC forms the 64-bit sum with two more instructions).
    if (!std::is_constant_evaluated()) {
      std::uint32_t lo = 0x80000000u, hi = 0;
      __asm__("umlal %[lo], %[hi], %[a], %[b]" : [lo] "+r"(lo), [hi] "+r"(hi) : [a] "r"(a), [b] "r"(b));
      return hi;
    }
#endif
    return static_cast<std::uint32_t>((std::uint64_t{a} * b + (std::uint64_t{1} << 31)) >> 32);
  } else {
    return mul_u25_u24_rounded_high_split(a, b);
  }
}

// x * g when the product fits int64, without __muldi3 on ARMv6-M: the low word's product (by
// low_product, exact) plus the high word's, which adds to the high word only.
template <std::uint64_t (*low_product)(std::uint32_t, std::uint32_t)>
[[gnu::always_inline]] constexpr std::int64_t mul_s64_by_word(std::int64_t x, std::uint32_t g) {
  if constexpr (has_long_multiply) {
    return x * static_cast<std::int64_t>(g);
  } else {
    const auto u = static_cast<std::uint64_t>(x);
    const std::uint64_t low = low_product(static_cast<std::uint32_t>(u), g);
    const std::uint32_t hi = static_cast<std::uint32_t>(low >> 32) + static_cast<std::uint32_t>(u >> 32) * g;
    return static_cast<std::int64_t>((std::uint64_t{hi} << 32) | static_cast<std::uint32_t>(low));
  }
}
// For 0 <= g < 2^16 (a 32 x 16 low product), and for any g < 2^32.
[[gnu::always_inline]] constexpr std::int64_t mul_s64_u16(std::int64_t x, std::uint32_t g) { return mul_s64_by_word<mul_u32_u16>(x, g); }
[[gnu::always_inline]] constexpr std::int64_t mul_s64_u32(std::int64_t x, std::uint32_t g) { return mul_s64_by_word<mul_u32>(x, g); }

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
[[gnu::always_inline]] constexpr std::uint32_t low_word_shifted_right(std::uint64_t x, int s) {
  const auto lo = static_cast<std::uint32_t>(x), hi = static_cast<std::uint32_t>(x >> 32);
  return (lo >> s) | ((hi << 1) << (31 - s));  // (hi << 1) << (31 - s): hi << (32 - s) without UB at s = 0
}
// Bits s .. s + 31 of x, 0 <= s < 64 (above bit 63: zeros): a shift that keeps one word.
[[gnu::always_inline]] constexpr std::uint32_t word_shifted_right(std::uint64_t x, int s) {
  return s < 32 ? low_word_shifted_right(x, s) : static_cast<std::uint32_t>(x >> 32) >> (s - 32);
}
// floor(x / 2^s), 0 <= s < 64, for a result that fits int32: the same without a 64-bit shift.
[[gnu::always_inline]] constexpr std::int32_t floor_shifted_right(std::int64_t x, int s) {
  const auto u = static_cast<std::uint64_t>(x);
  return s < 32 ? static_cast<std::int32_t>(low_word_shifted_right(u, s))
                : static_cast<std::int32_t>(static_cast<std::uint32_t>(u >> 32)) >> (s - 32);  // arithmetic: floor
}
// The least and the greatest of three, as nested compares: std::min({a, b, c}) builds its
// initializer list on the stack at -Os (Cortex-M0+: 15 instructions where these take 6).
[[gnu::always_inline]] constexpr std::int32_t least_of(std::int32_t a, std::int32_t b, std::int32_t c) {
  return a < b ? (a < c ? a : c) : (b < c ? b : c);
}
[[gnu::always_inline]] constexpr std::int32_t greatest_of(std::int32_t a, std::int32_t b, std::int32_t c) {
  return a > b ? (a > c ? a : c) : (b > c ? b : c);
}

// 2^s for 0 <= s < 64, built from words: a 64-bit shift by a run-time amount is an
// __aeabi_llsl call on ARMv6-M.
[[gnu::always_inline]] constexpr std::uint64_t power_of_two64(int s) {
  return s < 32 ? std::uint64_t{1u << s} : std::uint64_t{1u << (s - 32)} << 32;
}
// Number of bits needed to hold x (0 for 0), for 32-bit values: one 32-bit count (on ARMv6-M
// __clzsi2 alone, where bit_length's 64-bit count goes through __clzdi2).
constexpr int bit_length32(std::uint32_t x) { return x == 0 ? 0 : 32 - clz32(x); }
// bit_length from the word that holds the leading one: one 32-bit count, where clz64 is a
// __clzdi2 call (itself calling __clzsi2) on ARMv6-M.
constexpr int bit_length_by_words(std::uint64_t x) {
  const auto hi = static_cast<std::uint32_t>(x >> 32);
  return hi != 0 ? 64 - clz32(hi) : bit_length32(static_cast<std::uint32_t>(x));
}

// x 2^s as a 64-bit value, for any int32 x and 0 <= s < 32: the low word is x's shifted, the
// high word floor(x / 2^(32 - s)), the bits shifted out with the sign filling in.
[[gnu::always_inline]] constexpr std::int64_t widened_shifted_left(std::int32_t x, int s) {
  const auto hi = static_cast<std::uint32_t>((x >> 1) >> (31 - s));  // arithmetic shifts: (x >> 1) >> 31 at s = 0
  return static_cast<std::int64_t>((std::uint64_t{hi} << 32) | (static_cast<std::uint32_t>(x) << s));
}

// The high word of x << n, 0 <= n < 64 (with n = clz64(x): x's top 32 significant bits).
[[gnu::always_inline]] constexpr std::uint32_t high_word_shifted_left(std::uint64_t x, int n) {
  const auto lo = static_cast<std::uint32_t>(x), hi = static_cast<std::uint32_t>(x >> 32);
  return n >= 32 ? lo << (n - 32) : (hi << n) | ((lo >> 1) >> (31 - n));
}

// The high words of x << n and y << n for n = clz64(x), x > 0, y <= x: x's 32 bits from its
// leading one down and y's at the same places. One 32-bit count of the word that holds the
// leading one, where clz64 and two 64-bit shifts are a __clzdi2 call and two of
// high_word_shifted_left on ARMv6-M.
struct NormalisedPair {
  std::uint32_t x_top, y_top;
};
constexpr NormalisedPair normalised_pair(std::uint64_t x, std::uint64_t y) {
  const auto xh = static_cast<std::uint32_t>(x >> 32);
  const int n = xh != 0 ? clz32(xh) : 32 + clz32(static_cast<std::uint32_t>(x));  // clz64(x)
  return {high_word_shifted_left(x, n), high_word_shifted_left(y, n)};
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
