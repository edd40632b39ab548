// q arithmetic against the exact __int128 reference (q_reference.hpp) on corner
// cases and seeded random pairs. Every result must equal the correctly rounded
// one: nearest with ties away from zero (operators) or toward zero (*_trunc),
// then saturated. An independent long double check bounds the error by 0.5 LSB.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "q_formats.hpp"
#include "q_reference.hpp"

namespace {

namespace ref = q_reference;

#if defined(__SANITIZE_ADDRESS__)
constexpr int random_pairs = 4000;
#else
constexpr int random_pairs = 40000;
#endif

template <typename Q>
std::vector<std::pair<typename Q::storage, typename Q::storage>> test_pairs() {
  const auto corners = ref::corner_raws<Q>();
  std::vector<std::pair<typename Q::storage, typename Q::storage>> pairs;
  for (const auto a : corners)
    for (const auto b : corners) pairs.emplace_back(a, b);
  std::mt19937_64 rng(0x5EED0001u + static_cast<unsigned>(Q::frac_bits));
  for (int i = 0; i < random_pairs; ++i) pairs.emplace_back(ref::random_raw<Q>(rng), ref::random_raw<Q>(rng));
  return pairs;
}

// |result - exact| <= 0.5 LSB unless exact is out of range, where result must be the
// limit on exact's side. exact is in LSB units; long double holds 32-bit-format
// products exactly and quotients to 2^-63 relative.
template <typename Q>
void require_half_lsb(typename Q::storage result, long double exact) {
  if (exact >= static_cast<long double>(Q::raw_max) + 0.5L) {
    REQUIRE(result == Q::raw_max);
  } else if (exact <= static_cast<long double>(Q::raw_min) - 0.5L) {
    REQUIRE(result == Q::raw_min);
  } else {
    const long double error = static_cast<long double>(result) - exact;
    REQUIRE(std::fabs(error) <= 0.5L + std::fabs(exact) * 0x1p-60L);
  }
}

}  // namespace

TEMPLATE_TEST_CASE("q multiply and divide are correctly rounded and saturate", "[q]", Q_TEST_FORMATS) {
  using Q = TestType;
  for (const auto& [a, b] : test_pairs<Q>()) {
    const Q x = Q::from_raw(a), y = Q::from_raw(b);
    INFO("a=" << static_cast<long long>(a) << " b=" << static_cast<long long>(b));
    REQUIRE((x * y).raw() == ref::mul<Q>(a, b, true));
    REQUIRE(mul_trunc(x, y).raw() == ref::mul<Q>(a, b, false));
    REQUIRE((x / y).raw() == ref::div<Q>(a, b, true));
    REQUIRE(div_trunc(x, y).raw() == ref::div<Q>(a, b, false));
    if constexpr (sizeof(typename Q::storage) <= 4) {
      const long double scale = std::ldexp(1.0L, Q::frac_bits);
      require_half_lsb<Q>((x * y).raw(), static_cast<long double>(a) * static_cast<long double>(b) / scale);
      if (b != 0) require_half_lsb<Q>((x / y).raw(), static_cast<long double>(a) * scale / static_cast<long double>(b));
    }
  }
}

TEMPLATE_TEST_CASE("q add subtract and negate saturate while wrapping_add sub neg wrap", "[q]", Q_TEST_FORMATS) {
  using Q = TestType;
  for (const auto& [a, b] : test_pairs<Q>()) {
    const Q x = Q::from_raw(a), y = Q::from_raw(b);
    const ref::i128 wide_a = a, wide_b = b;
    INFO("a=" << static_cast<long long>(a) << " b=" << static_cast<long long>(b));
    REQUIRE((x + y).raw() == ref::saturate<Q>(wide_a + wide_b));
    REQUIRE((x - y).raw() == ref::saturate<Q>(wide_a - wide_b));
    REQUIRE((-x).raw() == ref::saturate<Q>(-wide_a));
    REQUIRE(wrapping_add(x, y).raw() == ref::wrap<Q>(wide_a + wide_b));
    REQUIRE(wrapping_sub(x, y).raw() == ref::wrap<Q>(wide_a - wide_b));
    REQUIRE(wrapping_neg(x).raw() == ref::wrap<Q>(-wide_a));
    REQUIRE((x < y) == (a < b));
    REQUIRE((x == y) == (a == b));
    REQUIRE((x >= y) == (a >= b));
  }
}

TEMPLATE_TEST_CASE("q saturates exactly at the limits and from_int is exact inside", "[q]", Q_TEST_FORMATS) {
  using Q = TestType;
  REQUIRE(Q::max().raw() == Q::raw_max);
  REQUIRE(Q::min().raw() == Q::raw_min);
  REQUIRE(Q::max() + Q::lsb() == Q::max());
  REQUIRE(Q::min() - Q::lsb() == Q::min());
  REQUIRE((Q::max() - Q::lsb()) + Q::lsb() == Q::max());  // reaches the limit without clipping
  REQUIRE(Q::max() + Q::min() == -Q::lsb());
  REQUIRE(-Q::min() == Q::max());
  REQUIRE(-Q::max() == wrapping_add(Q::min(), Q::lsb()));
  REQUIRE(wrapping_add(Q::max(), Q::lsb()) == Q::min());
  REQUIRE(Q::from_raw(0) / Q{} == Q{});
  REQUIRE(Q::lsb() / Q{} == Q::max());
  REQUIRE(-Q::lsb() / Q{} == Q::min());
  REQUIRE(Q::min() / Q{} == Q::min());
  REQUIRE(Q::from_int(-1) * Q::max() == -Q::max());  // -1.0 is representable in every format
  // from_raw clamps a raw outside a narrow format.
  if constexpr (Q::raw_max < std::numeric_limits<typename Q::storage>::max()) {
    REQUIRE(Q::from_raw(std::numeric_limits<typename Q::storage>::max()) == Q::max());
    REQUIRE(Q::from_raw(std::numeric_limits<typename Q::storage>::min()) == Q::min());
  }
  // from_int is exact in range and saturates outside.
  const std::int64_t int_max = static_cast<std::int64_t>(Q::max_magnitude >> Q::frac_bits);
  for (const std::int64_t n : {std::int64_t{0}, std::int64_t{1}, std::int64_t{-1}, int_max, -int_max - 1, int_max + 1,
                               -int_max - 2, INT64_MAX, INT64_MIN}) {
    INFO("n=" << n);
    REQUIRE(Q::from_int(n).raw() == ref::saturate<Q>(static_cast<ref::i128>(n) * ref::pow2(Q::frac_bits)));
  }
}
