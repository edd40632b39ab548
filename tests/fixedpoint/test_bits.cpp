// bits.hpp: mul_shift_wide against the exact __int128 floor, and the small helpers.
#include <catch2/catch.hpp>

#include <cstdint>
#include <initializer_list>
#include <random>
#include <utility>

#include "fixedpoint/bits.hpp"

namespace {

using i128 = __int128;

#if defined(__SANITIZE_ADDRESS__)
constexpr int random_cases = 1 << 16;
#else
constexpr int random_cases = 1 << 20;
#endif

// floor(a * b / 2^s); >> on a negative __int128 is arithmetic, i.e. floor.
i128 exact_mul_shift(std::int64_t a, std::int32_t b, int s) { return (static_cast<i128>(a) * b) >> s; }

bool fits_int64(i128 v) { return v >= INT64_MIN && v <= INT64_MAX; }

}  // namespace

TEST_CASE("mul_shift_wide equals the exact floored product whenever it fits int64", "[bits]") {
  std::mt19937_64 rng(0x5EED0010u);
  int checked = 0;
  for (int i = 0; i < random_cases; ++i) {
    // Random bit lengths for a, so that most products fit after the shift.
    const int length = static_cast<int>(rng() % 64u);
    const auto a = static_cast<std::int64_t>(rng()) >> (63 - length);
    std::int32_t b = static_cast<std::int32_t>(static_cast<std::uint32_t>(rng()));
    if (b == INT32_MIN) b = INT32_MIN + 1;  // the documented domain is |b| < 2^31
    const int s = static_cast<int>(rng() % 33u);
    const i128 expected = exact_mul_shift(a, b, s);
    if (!fits_int64(expected)) continue;
    ++checked;
    const std::int64_t got = fixedpoint::mul_shift_wide(a, b, s);
    if (got != static_cast<std::int64_t>(expected)) {  // report only failures: Catch per-check cost dominates
      INFO("a=" << a << " b=" << b << " s=" << s);
      REQUIRE(got == static_cast<std::int64_t>(expected));
    }
  }
  REQUIRE(checked > random_cases / 4);
}

TEST_CASE("mul_shift_wide corner cases", "[bits]") {
  // The high term alone is 2^63 here though the result fits (the fixed signed-overflow case).
  REQUIRE(fixedpoint::mul_shift_wide(INT64_MIN + 1, -1, 0) == INT64_MAX);
  REQUIRE(fixedpoint::mul_shift_wide(INT64_MIN, 1, 0) == INT64_MIN);
  REQUIRE(fixedpoint::mul_shift_wide(INT64_MIN, INT32_MAX, 32) ==
          static_cast<std::int64_t>(exact_mul_shift(INT64_MIN, INT32_MAX, 32)));
  REQUIRE(fixedpoint::mul_shift_wide(INT64_MAX, -INT32_MAX, 32) ==
          static_cast<std::int64_t>(exact_mul_shift(INT64_MAX, -INT32_MAX, 32)));
  REQUIRE(fixedpoint::mul_shift_wide(-1, 1, 32) == -1);  // floor, not truncation
  REQUIRE(fixedpoint::mul_shift_wide(-1, 1, 0) == -1);
  REQUIRE(fixedpoint::mul_shift_wide(0xFFFFFFFFll, 0x7FFFFFFF, 32) == 0x7FFFFFFE);
  static_assert(fixedpoint::mul_shift_wide(std::int64_t{1} << 40, 3, 8) == std::int64_t{3} << 32);
}

TEST_CASE("bit helpers", "[bits]") {
  static_assert(fixedpoint::bit_length(0) == 0 && fixedpoint::bit_length(1) == 1 && fixedpoint::bit_length(UINT64_MAX) == 64);
  static_assert(fixedpoint::clz32(1) == 31 && fixedpoint::clz64(std::uint64_t{1} << 40) == 23);
  static_assert(fixedpoint::saturate32(std::int64_t{1} << 40) == INT32_MAX && fixedpoint::saturate32(INT64_MIN) == INT32_MIN);
  SUCCEED();
  for (int b = 0; b < 64; ++b) {  // every leading-one position, with and without bits below it
    const std::uint64_t x = std::uint64_t{1} << b;
    CHECK(fixedpoint::bit_length_by_words(x) == b + 1);
    CHECK(fixedpoint::bit_length_by_words(x | (x - 1)) == b + 1);
  }
  CHECK(fixedpoint::bit_length_by_words(0) == 0);
}

// The ARMv6-M products (four 16x16 multiplies) against the host's native 64-bit product:
// the corners of every sign and magnitude, then 2^20 seeded random pairs per kind.
TEST_CASE("32x32 -> 64 products from 16-bit halves equal the native product", "[bits][multiply]") {
  const std::uint32_t corners[] = {0u, 1u, 2u, 0xFFFFu, 0x10000u, 0x7FFFFFFFu, 0x80000000u, 0x80000001u, 0xFFFFFFFEu, 0xFFFFFFFFu};
  for (const std::uint32_t a : corners) {
    for (const std::uint32_t b : corners) {
      REQUIRE(fixedpoint::mul_u32_halves(a, b) == std::uint64_t{a} * b);
      const auto sa = static_cast<std::int32_t>(a), sb = static_cast<std::int32_t>(b);
      REQUIRE(fixedpoint::mul_s32_halves(sa, sb) == std::int64_t{sa} * sb);
      REQUIRE(fixedpoint::mul_s32_u32_halves(sa, b) == std::int64_t{sa} * b);
    }
  }
  std::mt19937_64 random(20261122);
  for (int i = 0; i < (1 << 20); ++i) {
    const auto a = static_cast<std::uint32_t>(random()), b = static_cast<std::uint32_t>(random());
    const auto sa = static_cast<std::int32_t>(a), sb = static_cast<std::int32_t>(b);
    if (fixedpoint::mul_u32_halves(a, b) != std::uint64_t{a} * b || fixedpoint::mul_s32_halves(sa, sb) != std::int64_t{sa} * sb ||
        fixedpoint::mul_s32_u32_halves(sa, b) != std::int64_t{sa} * b) {
      FAIL("mismatch at a = " << a << ", b = " << b);
    }
  }
  STATIC_REQUIRE(fixedpoint::mul_s32_halves(-65536, 65537) == -65536LL * 65537);  // constexpr too
}

TEST_CASE("a 32x16 product from two 16x16 products equals the native product", "[bits][multiply]") {
  // The ARMv6-M formula, whatever this host's has_long_multiply says.
  auto two_products = [](std::uint32_t a, std::uint32_t b) {
    return (std::uint64_t{(a >> 16) * b} << 16) + (a & 0xFFFFu) * b;
  };
  const std::uint32_t wide[] = {0u, 1u, 0xFFFFu, 0x10000u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu};
  const std::uint32_t narrow[] = {0u, 1u, 2u, 0x8000u, 0xFFFEu, 0xFFFFu};
  for (const std::uint32_t a : wide) {
    for (const std::uint32_t b : narrow) {
      REQUIRE(two_products(a, b) == std::uint64_t{a} * b);
      REQUIRE(fixedpoint::mul_u32_u16(a, b) == std::uint64_t{a} * b);
    }
  }
  std::mt19937_64 random(20261201);
  for (int i = 0; i < random_cases; ++i) {
    const auto a = static_cast<std::uint32_t>(random()), b = static_cast<std::uint32_t>(random() & 0xFFFFu);
    if (two_products(a, b) != std::uint64_t{a} * b) FAIL("mismatch at a = " << a << ", b = " << b);
  }
}

TEST_CASE("the narrow products without a long multiply equal the native products on their domains", "[bits][multiply]") {
  // The ARMv6-M forms, whatever this host's has_long_multiply says: x in [0, 2^28], n < 2^13 and
  // 12 <= s < 32 for the shifted one; a < 2^25, b < 2^24 for the rounded high word.
  auto shifted = [](std::uint32_t x, std::uint32_t n, int s) { return std::uint64_t{x} * n >> s; };
  auto rounded_high = [](std::uint32_t a, std::uint32_t b) { return (std::uint64_t{a} * b + 0x80000000u) >> 32; };
  const std::uint32_t xs[] = {0u, 1u, 0xFFFu, 0x1000u, 0x1001u, (1u << 28) - 1u, 1u << 28};
  const std::uint32_t ns[] = {0u, 1u, 2u, 4095u, 4096u, 8191u};
  for (const std::uint32_t x : xs)
    for (const std::uint32_t n : ns)
      for (int s = 12; s < 32; ++s)
        REQUIRE(static_cast<std::uint64_t>(fixedpoint::mul_u28_u13_split(static_cast<std::int32_t>(x), static_cast<std::int32_t>(n), s)) ==
                shifted(x, n, s));
  const std::uint32_t as[] = {0u, 1u, 0xFFFFu, 0x10000u, 0x1FFFFFFu}, bs[] = {0u, 1u, 0xFFFFu, 0x10000u, 0xFFFFFFu, 0xFF0000u};
  for (const std::uint32_t a : as)
    for (const std::uint32_t b : bs) REQUIRE(fixedpoint::mul_u25_u24_rounded_high_split(a, b) == rounded_high(a, b));
  std::mt19937_64 random(20261207);
  for (int i = 0; i < random_cases; ++i) {
    const auto x = static_cast<std::uint32_t>(random() % ((1u << 28) + 1u)), n = static_cast<std::uint32_t>(random() & 0x1FFFu);
    const int s = 12 + static_cast<int>(random() % 20u);
    if (static_cast<std::uint64_t>(fixedpoint::mul_u28_u13_split(static_cast<std::int32_t>(x), static_cast<std::int32_t>(n), s)) !=
        shifted(x, n, s))
      FAIL("mul_u28_u13_split: x = " << x << ", n = " << n << ", s = " << s);
    const auto a = static_cast<std::uint32_t>(random() & 0x1FFFFFFu), b = static_cast<std::uint32_t>(random() & 0xFFFFFFu);
    if (fixedpoint::mul_u25_u24_rounded_high_split(a, b) != rounded_high(a, b)) FAIL("mul_u25_u24_rounded_high_split: a = " << a << ", b = " << b);
  }
  // This host's forms, at compile time.
  STATIC_REQUIRE(fixedpoint::mul_u28_u13_shifted(1 << 28, 8191, 20) == 8191 << 8);
  STATIC_REQUIRE(fixedpoint::mul_u25_u24_rounded_high(0x1FFFFFFu, 0xFFFFFFu) == (1u << 17));  // (2^25 - 1)(2^24 - 1) / 2^32 = 2^17 - 0.012
}

TEST_CASE("64-bit shifts by less than 32 from 32-bit operations equal the native shifts", "[bits][shift]") {
  std::mt19937_64 random(20261201);
  for (int i = 0; i < random_cases; ++i) {
    const std::uint64_t x = random() >> (random() % 64);  // every magnitude
    const int s = static_cast<int>(random() % 32);
    if (fixedpoint::low_word_shifted_right(x, s) != static_cast<std::uint32_t>(x >> s)) FAIL("x >> s at x = " << x << ", s = " << s);
    const auto w = static_cast<std::int32_t>(static_cast<std::uint32_t>(x));  // either sign
    if (fixedpoint::widened_shifted_left(w, s) != std::int64_t{w} * (std::int64_t{1} << s)) FAIL("x 2^s at x = " << w << ", s = " << s);
    if (x != 0) {
      const int n = fixedpoint::clz64(x);
      if (fixedpoint::high_word_shifted_left(x, n) != static_cast<std::uint32_t>((x << n) >> 32))
        FAIL("top word at x = " << x);
    }
    const int any = static_cast<int>(random() % 64);
    if (fixedpoint::high_word_shifted_left(x, any) != static_cast<std::uint32_t>((x << any) >> 32))
      FAIL("high word of x << " << any << " at x = " << x);
  }
  for (const int s : {0, 1, 31}) {  // the ends of the range, where a naive hi << (32 - s) would be undefined
    REQUIRE(fixedpoint::low_word_shifted_right(0xFFFFFFFFFFFFFFFFull, s) == static_cast<std::uint32_t>(0xFFFFFFFFFFFFFFFFull >> s));
    for (const std::int32_t w : {INT32_MIN, -1, INT32_MAX})
      REQUIRE(fixedpoint::widened_shifted_left(w, s) == std::int64_t{w} * (std::int64_t{1} << s));
  }
  STATIC_REQUIRE(fixedpoint::high_word_shifted_left(1, 63) == 0x80000000u);
}

TEST_CASE("power_of_two64 is 2^s at every s from 0 to 63", "[bits][shift]") {
  for (int s = 0; s < 64; ++s) {
    INFO("s = " << s);
    REQUIRE(fixedpoint::power_of_two64(s) == std::uint64_t{1} << s);
  }
  STATIC_REQUIRE(fixedpoint::power_of_two64(32) == 0x100000000ull);
}

TEST_CASE("normalised_pair gives the top word of x and y shifted by clz64(x)", "[bits][shift]") {
  std::mt19937_64 random(20261206);
  const auto expected = [](std::uint64_t x, std::uint64_t y) {
    const int n = __builtin_clzll(x);
    return std::pair{static_cast<std::uint32_t>((x << n) >> 32), static_cast<std::uint32_t>((y << n) >> 32)};
  };
  for (int i = 0; i < random_cases; ++i) {
    const std::uint64_t x = (random() >> (random() % 64)) | 1u;  // every magnitude, never 0
    const std::uint64_t y = random() % 4 == 0 ? x : (x == ~0ull ? random() : random() % (x + 1));  // y <= x, x itself too
    const fixedpoint::NormalisedPair p = fixedpoint::normalised_pair(x, y);
    if (std::pair{p.x_top, p.y_top} != expected(x, y)) FAIL("x = " << x << ", y = " << y);
  }
  // Where the leading one crosses the word boundary, and the ends.
  for (const std::uint64_t x : std::initializer_list<std::uint64_t>{1, 0xFFFFFFFF, 0x100000000, 0x1FFFFFFFF, 0x80000000'00000000, ~std::uint64_t{0}}) {
    for (const std::uint64_t y : {std::uint64_t{0}, std::uint64_t{1}, x / 3, x - 1, x}) {
      const fixedpoint::NormalisedPair p = fixedpoint::normalised_pair(x, y);
      CHECK(std::pair{p.x_top, p.y_top} == expected(x, y));
    }
  }
  STATIC_REQUIRE(fixedpoint::normalised_pair(0x100000000ull, 0x80000000ull).y_top == 0x40000000u);
}
