// multiply_check: every 32 x 32 -> 64 product of fixedpoint/bits.hpp (mul_u32, mul_s32,
// mul_s32_u32, mul_s32_nonnegative, mul_s32_setup, mul_u32_u16, mul_s64_u16, mul_s64_u32, and
// the narrow ones mul_u28_u13_shifted and mul_u25_u24_rounded_high on their domains) against the compiler's
// int64 multiply (libgcc's __aeabi_lmul on Cortex-M0+, an independent implementation), over
// the operands' edge values paired with each other and 2^20 pseudo-random pairs. On Cortex-M0+
// the first four are Thumb-1 assembly that the host never runs: frames equal to the host's
// cover them only as far as the scenes' operands go. Logs the count of wrong products and
// returns 1 if there is one.
#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "hal/hal.hpp"
#include "hal/log_line.hpp"

namespace {

// volatile: the reference product must be computed at run time, by the compiler's multiply.
volatile std::int64_t sink;

std::uint32_t wrong = 0;

void check(std::uint32_t a, std::uint32_t b) {
  using namespace fixedpoint;
  const auto sa = static_cast<std::int32_t>(a), sb = static_cast<std::int32_t>(b);
  const std::uint64_t unsigned_product = std::uint64_t{a} * b;
  const std::int64_t signed_product = std::int64_t{sa} * sb;
  const std::int64_t mixed_product = std::int64_t{sa} * static_cast<std::int64_t>(b);
  wrong += mul_u32(a, b) != unsigned_product;
  wrong += mul_s32(sa, sb) != signed_product;
  wrong += mul_s32_u32(sa, b) != mixed_product;
  const std::int32_t nonnegative = static_cast<std::int32_t>(b & 0x7FFFFFFFu);
  wrong += mul_s32_nonnegative(sa, nonnegative) != std::int64_t{sa} * nonnegative;
  wrong += mul_s32_setup(sa, sb) != signed_product;
  wrong += mul_u32_u16(a, b & 0xFFFFu) != std::uint64_t{a} * (b & 0xFFFFu);
  // A 64-bit factor whose product with b fits int64: the signed product shifted into the high word.
  const std::int64_t wide = signed_product >> 20;
  wrong += mul_s64_u16(wide, b & 0xFFFFu) != wide * static_cast<std::int64_t>(b & 0xFFFFu);
  wrong += mul_s64_u32(wide >> 12, b) != (wide >> 12) * static_cast<std::int64_t>(b);
  // x in [0, 2^28] and n < 2^13, shifted by 12 .. 31; a < 2^25 and b < 2^24, rounded at 2^32.
  const std::uint32_t x = a % ((1u << 28) + 1u), n = b & 0x1FFFu;
  const int shift = 12 + static_cast<int>((a ^ b) % 20u);
  wrong += static_cast<std::uint32_t>(mul_u28_u13_shifted(static_cast<std::int32_t>(x), static_cast<std::int32_t>(n), shift)) !=
           static_cast<std::uint32_t>(std::uint64_t{x} * n >> shift);
  const std::uint32_t a25 = a >> 7, b24 = b >> 8;
  wrong += mul_u25_u24_rounded_high(a25, b24) != static_cast<std::uint32_t>((std::uint64_t{a25} * b24 + 0x80000000u) >> 32);
  sink = signed_product;
}

}  // namespace

int spanlight::hal::app_main(Args /*args*/) {
  constexpr std::uint32_t edges[] = {0u,          1u,          2u,          0xFFFFu,     0x10000u,    0x10001u,
                                     0x7FFFu,     0x8000u,     0x7FFFFFFFu, 0x80000000u, 0x80000001u, 0xFFFF0000u,
                                     0xFFFF8000u, 0xFFFFFFFEu, 0xFFFFFFFFu, 0x12345678u, 0xDEADBEEFu};
  std::uint32_t count = 0;
  for (const std::uint32_t a : edges) {
    for (const std::uint32_t b : edges) {
      check(a, b);
      ++count;
    }
  }
  std::uint32_t state = 0x9E3779B9u;  // xorshift32
  auto next = [&] {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return state;
  };
  for (std::uint32_t n = 0; n < (1u << 20); ++n) {
    const std::uint32_t a = next(), b = next();
    // Every eighth pair with one factor's high half cleared or set, where carries and the sign
    // corrections change.
    check(n % 8 == 0 ? a & 0xFFFFu : (n % 8 == 1 ? a | 0xFFFF0000u : a), b);
    ++count;
  }
  log_line(LogLine() << "multiply_check: " << count << " operand pairs, " << wrong << " wrong products");
  return wrong == 0 ? 0 : 1;
}
