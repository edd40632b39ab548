// fixedpoint::reciprocal against the exact 1/d: every 16-bit d, plus seeded
// random 32-bit and 64-bit d, for each table size and Newton step count. The
// measured maximum must stay under the bound derived (not tuned) in
// reciprocal_error.hpp / docs/reciprocal.md.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "reciprocal_error.hpp"

namespace {

using namespace reciprocal_error;

// The sanitizer twin is ~10x slower: it keeps the exhaustive sweep, samples less.
#if defined(__SANITIZE_ADDRESS__)
constexpr std::uint32_t random_count = 1u << 16;
#else
constexpr std::uint32_t random_count = 1u << 20;
#endif
constexpr std::uint32_t seed = 20240601u;

template <int B, int Steps>
void check_bound() {
  const Stats u16 = exhaustive_u16<B, Steps>();
  const Stats u32 = random_u32<B, Steps>(seed, random_count);
  const Stats u64 = random_u64<B, Steps>(seed + 1, random_count);
  const long double bound = bound_u32(B, Steps);
  const long double bound64 = bound_u64(B, Steps);

  Stats all32 = u16;
  all32.merge(u32);
  std::printf("| %2d | %d | %.3Le (2^%.2Lf) | %.3Le (2^%.2Lf) | %.3Le | bound %.3Le (2^%.2Lf) |\n", B, Steps,
              all32.max_error, std::log2(all32.max_error), u64.max_error, std::log2(u64.max_error),
              u16.max_error, bound, std::log2(bound));

  INFO("B=" << B << " steps=" << Steps << " worst 32-bit d=" << all32.worst_d << " worst 64-bit d=" << u64.worst_d);
  REQUIRE(u16.count == 65535u);
  REQUIRE(u16.max_error <= bound);
  REQUIRE(u32.max_error <= bound);
  REQUIRE(u64.max_error <= bound64);

  // The documented mantissa range: [2^30 * (1 - e), 2^31).
  Stats all = all32;
  all.merge(u64);
  REQUIRE(all.max_mantissa < (1u << 31));
  REQUIRE(static_cast<long double>(all.min_mantissa) >= static_cast<long double>(1u << 30) * (1.0L - bound));
}

template <int B>
void check_all_steps() {
  std::printf("| B | steps | max rel error, 32-bit d | max rel error, 64-bit d | 16-bit d only | proven bound |\n");
  check_bound<B, 0>();
  check_bound<B, 1>();
  check_bound<B, 2>();
}

}  // namespace

TEST_CASE("reciprocal error with a 6-bit table", "[reciprocal]") { check_all_steps<6>(); }
TEST_CASE("reciprocal error with a 8-bit table", "[reciprocal]") { check_all_steps<8>(); }
TEST_CASE("reciprocal error with a 10-bit table", "[reciprocal]") { check_all_steps<10>(); }
TEST_CASE("reciprocal error with a 12-bit table", "[reciprocal]") { check_all_steps<12>(); }

TEST_CASE("reciprocal: the 64-bit overload equals the 32-bit one below 2^32", "[reciprocal]") {
  for (std::uint32_t d = 1; d <= 0xFFFFu; ++d) {
    const fixedpoint::Reciprocal narrow = fixedpoint::reciprocal<8, 2>(d);
    const fixedpoint::Reciprocal wide = fixedpoint::reciprocal<8, 2>(std::uint64_t{d});
    REQUIRE(narrow.mantissa == wide.mantissa);
    REQUIRE(narrow.shift == wide.shift);
  }
  std::mt19937 rng(seed);
  for (int i = 0; i < 4096; ++i) {
    const std::uint32_t d = static_cast<std::uint32_t>(rng()) | 1u;
    REQUIRE(fixedpoint::reciprocal<10, 1>(d).mantissa == fixedpoint::reciprocal<10, 1>(std::uint64_t{d}).mantissa);
  }
}

TEST_CASE("reciprocal: the table and powers of two are what the header states", "[reciprocal]") {
  // Entry 0 is round(2^16 / (1 + 2^-(B+1))) and every entry is in (2^15, 2^16).
  static_assert(fixedpoint::reciprocal_table<8>.entry[0] == 65408);  // 2^16 / (1 + 2^-9) = 65408.12
  for (const std::uint16_t e : fixedpoint::reciprocal_table<12>.entry) {
    REQUIRE(e > (1u << 15));
  }
  // 1/2^k: the shift follows the leading-zero count; the mantissa is below 2^31 by at
  // most the 2-step bound, 2^31 * (2^-29 + tiny) < 8.
  constexpr fixedpoint::Reciprocal quarter = fixedpoint::reciprocal<8, 2>(std::uint32_t{4});
  static_assert(quarter.shift == 62 - 29);
  static_assert(quarter.mantissa < (1u << 31) && quarter.mantissa > (1u << 31) - 8u);
  constexpr fixedpoint::Reciprocal big = fixedpoint::reciprocal<8, 2>(std::uint64_t{1} << 40);
  static_assert(big.shift == 94 - 23 && big.mantissa == quarter.mantissa);
}
