// Two 16-bit lanes in one 32-bit word: the few packed operations the texture
// blend needs. Cortex-M4 and M7 have each as one DSP instruction (arm_acle.h);
// elsewhere (the host, Cortex-M0+) a portable form gives the same bits, so
// host and target agree to the byte.
#pragma once

#include <bit>
#include <cstdint>

#if defined(__ARM_FEATURE_SIMD32) && __ARM_FEATURE_SIMD32
#include <arm_acle.h>
#define FIXEDPOINT_HAS_DSP 1
#else
#define FIXEDPOINT_HAS_DSP 0
#endif

namespace fixedpoint {

inline constexpr bool has_dsp = FIXEDPOINT_HAS_DSP != 0;

// Bytes 0 and 2 of x as two 16-bit lanes: x & 0x00FF00FF.
[[gnu::always_inline]] inline std::uint32_t bytes_0_2(std::uint32_t x) {
#if FIXEDPOINT_HAS_DSP
  return __uxtb16(x);
#else
  return x & 0x00FF00FFu;
#endif
}

// Bytes 1 and 3 of x as two lanes: (x >> 8) & 0x00FF00FF.
[[gnu::always_inline]] inline std::uint32_t bytes_1_3(std::uint32_t x) {
#if FIXEDPOINT_HAS_DSP
  std::uint32_t r;
  asm("uxtb16 %0, %1, ror #8" : "=r"(r) : "r"(x));  // GCC 12 does not fold the rotation itself
  return r;
#else
  return (x >> 8) & 0x00FF00FFu;
#endif
}

// a + bytes_1_3(b), lane by lane (each lane's sum must stay below 2^16).
[[gnu::always_inline]] inline std::uint32_t add_bytes_1_3(std::uint32_t a, std::uint32_t b) {
#if FIXEDPOINT_HAS_DSP
  std::uint32_t r;
  asm("uxtab16 %0, %1, %2, ror #8" : "=r"(r) : "r"(a), "r"(b));
  return r;
#else
  return a + ((b >> 8) & 0x00FF00FFu);
#endif
}

// Byte 1 of a in lane 0 and byte 1 of b in lane 1: (a >> 8 & 255) | (b >> 8 & 255) << 16,
// for texels 0x00RRGGBB (byte 3 zero): their greens as a pair.
[[gnu::always_inline]] inline std::uint32_t pair_byte_1(std::uint32_t a, std::uint32_t b) {
#if FIXEDPOINT_HAS_DSP
  std::uint32_t g, r;
  asm("uxtb16 %0, %1, ror #8" : "=r"(g) : "r"(a));
  asm("uxtab16 %0, %1, %2, ror #24" : "=r"(r) : "r"(g), "r"(b));  // b rotated: its byte 1 in byte 2, its byte 3 (0) in byte 0
  return r;
#else
  return ((a >> 8) & 255u) | (((b >> 8) & 255u) << 16);
#endif
}

// lane0(a) * lane0(b) + lane1(a) * lane1(b), lanes below 2^15 (signed in the DSP form).
[[gnu::always_inline]] inline std::uint32_t dot_lanes(std::uint32_t a, std::uint32_t b) {
#if FIXEDPOINT_HAS_DSP
  return static_cast<std::uint32_t>(__smuad(static_cast<std::int32_t>(a), static_cast<std::int32_t>(b)));
#else
  return (a & 0xFFFFu) * (b & 0xFFFFu) + (a >> 16) * (b >> 16);
#endif
}

// lane0(a) lane0(b) + lane1(a) lane1(b) + acc, each lane a signed 16-bit value (one smlad), modulo 2^32
// as the instruction is (the callers' sums fit an int32).
[[gnu::always_inline]] inline std::int32_t dot_signed_lanes_plus(std::uint32_t a, std::uint32_t b, std::int32_t acc) {
#if FIXEDPOINT_HAS_DSP
  return __smlad(static_cast<std::int32_t>(a), static_cast<std::int32_t>(b), acc);
#else
  auto lane = [](std::uint32_t x, int k) { return std::int64_t{static_cast<std::int16_t>(static_cast<std::uint16_t>(x >> (16 * k)))}; };
  return static_cast<std::int32_t>(lane(a, 0) * lane(b, 0) + lane(a, 1) * lane(b, 1) + acc);
#endif
}

// Lane 0 of a and lane 0 of b as a pair (a's in lane 0); the same for lane 1.
[[gnu::always_inline]] inline std::uint32_t low_lanes(std::uint32_t a, std::uint32_t b) {
#if FIXEDPOINT_HAS_DSP
  std::uint32_t r;
  asm("pkhbt %0, %1, %2, lsl #16" : "=r"(r) : "r"(a), "r"(b));  // GCC 12 builds it from a mask and an OR
  return r;
#else
  return (a & 0xFFFFu) | (b << 16);
#endif
}
[[gnu::always_inline]] inline std::uint32_t high_lanes(std::uint32_t a, std::uint32_t b) {
#if FIXEDPOINT_HAS_DSP
  std::uint32_t r;
  asm("pkhtb %0, %1, %2, asr #16" : "=r"(r) : "r"(b), "r"(a));
  return r;
#else
  return (a >> 16) | (b & 0xFFFF0000u);
#endif
}

// The two lanes' products: lane0(a) * lane0(b) and lane1(a) * lane1(b), each below 2^16.
[[gnu::always_inline]] inline std::uint32_t lane_products(std::uint32_t a, std::uint32_t b) {
#if FIXEDPOINT_HAS_DSP
  std::uint32_t top, bottom;  // lanes below 2^15 here (8-bit levels), so the signed products are the unsigned ones
  asm("smultt %0, %1, %2" : "=r"(top) : "r"(a), "r"(b));
  asm("smulbb %0, %1, %2" : "=r"(bottom) : "r"(a), "r"(b));
  return (top << 16) | bottom;
#else
  return (((a >> 16) * (b >> 16)) << 16) | ((a & 0xFFFFu) * (b & 0xFFFFu));
#endif
}

// Each byte of a + b, saturated at 255.
[[gnu::always_inline]] inline std::uint32_t add_bytes_saturated(std::uint32_t a, std::uint32_t b) {
#if FIXEDPOINT_HAS_DSP
  return __uqadd8(a, b);
#else
  const std::uint32_t low7 = (a & 0x7F7F7F7Fu) + (b & 0x7F7F7F7Fu);  // no carry leaves a byte
  const std::uint32_t sum = low7 ^ ((a ^ b) & 0x80808080u);           // each byte's sum mod 256
  const std::uint32_t carry = ((a & b) | ((a | b) & ~sum)) & 0x80808080u;  // each byte's carry out
  return sum | ((carry >> 7) * 255u);
#endif
}

// x as a value the compiler must hold in a register: a product by it stays one
// multiply instead of a chain of shifts and adds (which needs no register, but
// costs three or four instructions where the multiply costs one).
[[gnu::always_inline]] inline std::uint32_t opaque(std::uint32_t x) {
#if defined(__arm__)
  asm("" : "+r"(x));
#endif
  return x;
}

}  // namespace fixedpoint
