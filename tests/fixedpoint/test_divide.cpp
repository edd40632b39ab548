// div_mod and divide_rounded (divide.hpp) against the exact integer quotient,
// over their whole contract: d in [1, 2^32), n / d < 2^32.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>

#include "fixedpoint/divide.hpp"

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr int random_cases = 1 << 15;
#else
constexpr int random_cases = 1 << 20;
#endif

void require_exact(std::uint64_t n, std::uint32_t d) {
  const fixedpoint::DivMod qr = fixedpoint::div_mod(n, d);
  INFO("n " << n << ", d " << d);
  REQUIRE(qr.quotient == n / d);
  REQUIRE(qr.remainder == n % d);
}

// A uniform quotient bound: n below d * 2^k for a random k in [0, 32].
std::uint64_t random_numerator(std::mt19937_64& rng, std::uint32_t d) {
  const int k = static_cast<int>(rng() % 33);
  const std::uint64_t limit = (std::uint64_t{d} << k) - 1;  // < 2^64
  return limit == 0 ? 0 : rng() % limit;
}

}  // namespace

TEST_CASE("div_mod is the exact quotient and remainder over the contract", "[divide]") {
  std::mt19937_64 rng(20240620);
  for (int i = 0; i < random_cases; ++i) {
    const auto d = static_cast<std::uint32_t>(rng() >> (32 + rng() % 32)) | 1u;  // every bit length
    require_exact(random_numerator(rng, d), d);
  }
  // The ends: d = 1 and the largest d, quotients just below 2^32, exact multiples and their neighbours.
  for (const std::uint32_t d : {1u, 2u, 3u, 7u, 65535u, 65536u, 2147483647u, 2147483648u, 4294967295u}) {
    const std::uint64_t top = (std::uint64_t{d} << 32) - 1;
    for (const std::uint64_t n : {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{d} - 1, std::uint64_t{d},
                                  std::uint64_t{d} + 1, top, top - 1, top - d, top / 2, std::uint64_t{d} * 4294967295u}) {
      require_exact(n, d);
    }
  }
}

TEST_CASE("divide_rounded rounds to nearest with ties away from zero", "[divide]") {
  REQUIRE(fixedpoint::divide_rounded(5, 2) == 3);
  REQUIRE(fixedpoint::divide_rounded(-5, 2) == -3);
  REQUIRE(fixedpoint::divide_rounded(7, 4) == 2);
  REQUIRE(fixedpoint::divide_rounded(-7, 4) == -2);
  REQUIRE(fixedpoint::divide_rounded(5, 4) == 1);
  REQUIRE(fixedpoint::divide_rounded(0, 9) == 0);
  std::mt19937_64 rng(20240621);
  for (int i = 0; i < random_cases; ++i) {
    const auto d = static_cast<std::uint32_t>(rng() >> (32 + rng() % 32)) | 1u;
    const auto magnitude = static_cast<std::int64_t>(random_numerator(rng, d) >> 1);  // < 2^63
    const std::int64_t n = (rng() & 1) ? -magnitude : magnitude;
    const std::int64_t q = fixedpoint::divide_rounded(n, d);
    // |n - q d| <= d / 2, and on a tie q is the one away from zero: 2 |n - q d| < d or (= d and |q| > |n| / d).
    const __int128 twice_error = 2 * (static_cast<__int128>(n) - static_cast<__int128>(q) * d);
    const __int128 abs_twice = twice_error < 0 ? -twice_error : twice_error;
    INFO("n " << n << ", d " << d << ", q " << q);
    REQUIRE(abs_twice <= d);
    if (abs_twice == d) REQUIRE((n >= 0 ? q * static_cast<__int128>(d) > n : q * static_cast<__int128>(d) < n));
  }
}

TEST_CASE("floor_div_wide is the exact floor and remainder for every 64-bit numerator", "[divide]") {
  auto require_floor = [](std::int64_t n, std::uint32_t d) {
    const fixedpoint::WideFloorDivMod qr = fixedpoint::floor_div_wide(n, d);
    // The floor from __int128: q d <= n < (q + 1) d, r = n - q d.
    const __int128 wide_n = n, wide_d = d;
    __int128 q = wide_n / wide_d;
    if (q * wide_d > wide_n) --q;
    INFO("n " << n << ", d " << d);
    REQUIRE(qr.quotient == static_cast<std::int64_t>(q));
    REQUIRE(static_cast<__int128>(qr.remainder) == wide_n - q * wide_d);
  };
  std::mt19937_64 rng(20261205);
  for (int i = 0; i < random_cases; ++i) {
    const auto d = static_cast<std::uint32_t>(rng() >> (32 + rng() % 32)) | 1u;  // every bit length
    const auto magnitude = static_cast<std::int64_t>(rng() >> (1 + rng() % 63));  // every bit length below 2^63
    require_floor((rng() & 1) ? -magnitude : magnitude, d);
  }
  // The ends: both signs around multiples, the largest magnitudes, d = 1 and d = 2^32 - 1.
  for (const std::uint32_t d : {1u, 2u, 3u, 256u, 65535u, 1073741568u, 2147483648u, 4294967295u}) {
    for (const std::int64_t n : {std::int64_t{0}, std::int64_t{1}, std::int64_t{d} - 1, std::int64_t{d}, std::int64_t{d} + 1,
                                 INT64_MAX, INT64_MAX - 1, (std::int64_t{d} << 30) - 1})
      for (const std::int64_t signed_n : {n, -n}) require_floor(signed_n, d);
  }
  // Usable where the edge setup needs it, at compile time.
  static_assert(fixedpoint::floor_div_wide(-7, 2).quotient == -4 && fixedpoint::floor_div_wide(-7, 2).remainder == 1);
}

// The path a core without a divide instruction takes (Cortex-M0+), run here on the host: from the
// divisor's reciprocal, the exact quotient in fewer than the 6 steps divide.hpp states.
TEST_CASE("FloorDivisor without a divide instruction gives the exact quotient in a few steps", "[divide]") {
  std::mt19937_64 rng(20261207);
  int worst = 0;
  auto check = [&](std::uint32_t n, std::uint32_t d) {
    const fixedpoint::Reciprocal y = fixedpoint::reciprocal<8, 2>(d);
    const std::uint32_t q = fixedpoint::FloorDivisor::quotient_by_reciprocal(n, d, y);
    const auto q0 = fixedpoint::word_shifted_right(fixedpoint::mul_u32(n, y.mantissa), y.shift);
    INFO("n " << n << ", d " << d);
    REQUIRE(q == n / d);
    REQUIRE(q0 <= q);  // the reciprocal is from below: the steps only go up
    worst = std::max(worst, static_cast<int>(q - q0));
  };
  for (int i = 0; i < random_cases; ++i) {
    const auto d = static_cast<std::uint32_t>(rng() >> (33 + rng() % 31)) | 1u;  // every bit length below 2^31 (shifts 33..63)
    check(static_cast<std::uint32_t>(rng() >> (32 + rng() % 32)), d);              // every bit length of n
  }
  for (const std::uint32_t d : {1u, 3u, 255u, 256u, 65535u, 0x7FFFFFFFu})
    for (const std::uint32_t n : {0u, d - 1, d, 0xFFFFFFFFu - 1, 0xFFFFFFFFu}) check(n, d);
  INFO("most correction steps: " << worst);
  REQUIRE(worst < 6);
}
