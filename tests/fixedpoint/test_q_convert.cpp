// q conversions: from_double / from_float (rounding, saturation, NaN, inf),
// to_double, and q_cast between formats, against the exact reference.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "q_formats.hpp"
#include "q_reference.hpp"

namespace {

namespace ref = q_reference;
using namespace q_formats;

constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();
constexpr double inf_value = std::numeric_limits<double>::infinity();

template <typename Q>
void require_from_double(double x) {
  INFO("x=" << x);
  REQUIRE(Q::from_double(x).raw() == ref::from_double<Q>(x, true));
  REQUIRE(Q::from_double_trunc(x).raw() == ref::from_double<Q>(x, false));
}

// A random double whose scaled magnitude is spread over [2^-8, 2^(magnitude_bits + 8)] LSB.
template <typename Q>
double random_double(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> mantissa(1.0, 2.0);
  const int exponent = static_cast<int>(rng() % static_cast<std::uint64_t>(Q::magnitude_bits + 17)) - 8 - Q::frac_bits;
  const double x = std::ldexp(mantissa(rng), exponent);
  return (rng() & 1u) ? -x : x;
}

template <typename To, typename From>
void check_cast(std::mt19937_64& rng) {
  auto check = [](typename From::storage a) {
    INFO("from raw " << static_cast<long long>(a));
    REQUIRE(fixedpoint::q_cast<To>(From::from_raw(a)).raw() == ref::cast<To, From>(a, true));
    REQUIRE(fixedpoint::q_cast_trunc<To>(From::from_raw(a)).raw() == ref::cast<To, From>(a, false));
  };
  for (const auto a : ref::corner_raws<From>()) check(a);
  for (int i = 0; i < 2000; ++i) check(ref::random_raw<From>(rng));
}

template <typename From>
void check_cast_to_all(std::mt19937_64& rng) {
  check_cast<q15_16, From>(rng);
  check_cast<q1_30, From>(rng);
  check_cast<q0_31, From>(rng);
  check_cast<q31_0, From>(rng);
  check_cast<q10_10, From>(rng);
  check_cast<q7_8_s16, From>(rng);
  check_cast<q0_15_s16, From>(rng);
  check_cast<q24_8_s64, From>(rng);
  check_cast<q31_32_s64, From>(rng);
  check_cast<q0_63_s64, From>(rng);
  check_cast<q20_40_s64, From>(rng);
}

}  // namespace

TEMPLATE_TEST_CASE("q from_double rounds ties away from zero and saturates", "[q]", Q_TEST_FORMATS) {
  using Q = TestType;
  const double lsb = std::ldexp(1.0, -Q::frac_bits);
  // Corner raws, and every raw +-0.25, +-0.5 (ties) and +-0.75 LSB where double can hold it.
  for (const auto r : ref::corner_raws<Q>()) {
    const double x = static_cast<double>(r) * lsb;
    require_from_double<Q>(x);
    if (Q::magnitude_bits <= 50) {
      for (const double offset : {0.25, 0.5, 0.75, -0.25, -0.5, -0.75}) require_from_double<Q>(x + offset * lsb);
    }
  }
  std::mt19937_64 rng(0x5EED0002u);
  for (int i = 0; i < 20000; ++i) require_from_double<Q>(random_double<Q>(rng));

  REQUIRE(Q::from_double(nan_value) == Q{});
  REQUIRE(Q::from_double(-nan_value) == Q{});
  REQUIRE(Q::from_double(inf_value) == Q::max());
  REQUIRE(Q::from_double(-inf_value) == Q::min());
  REQUIRE(Q::from_double(1e300) == Q::max());
  REQUIRE(Q::from_double(-1e300) == Q::min());
  REQUIRE(Q::from_double(-0.0) == Q{});
  REQUIRE(Q::from_double(std::numeric_limits<double>::denorm_min()) == Q{});
  REQUIRE(Q::from_float(std::numeric_limits<float>::quiet_NaN()) == Q{});
  REQUIRE(Q::from_float(std::numeric_limits<float>::infinity()) == Q::max());
  REQUIRE(Q::from_float(-std::numeric_limits<float>::infinity()) == Q::min());
  if constexpr (Q::frac_bits >= 1) {
    REQUIRE(Q::from_double(0.5).raw() == static_cast<typename Q::storage>(ref::pow2(Q::frac_bits - 1)));
    REQUIRE(Q::from_double(-0.5).raw() == static_cast<typename Q::storage>(-ref::pow2(Q::frac_bits - 1)));
    REQUIRE(Q::from_float(0.5f).raw() == static_cast<typename Q::storage>(ref::pow2(Q::frac_bits - 1)));
  }
  // The limits themselves: the exact range is [-2^m, 2^m - 1] LSB.
  const double top = std::ldexp(1.0, Q::int_bits);  // = (raw_max + 1) LSB
  REQUIRE(Q::from_double(top) == Q::max());
  REQUIRE(Q::from_double(-top) == Q::min());
  if (Q::magnitude_bits <= 50) {
    REQUIRE(Q::from_double(top - 0.5 * lsb) == Q::max());        // a tie just past max rounds up, then saturates
    REQUIRE(Q::from_double(top - 0.75 * lsb) == Q::max());
    REQUIRE(Q::from_double(-top - 0.5 * lsb) == Q::min());
    REQUIRE(Q::from_double(-top + 0.5 * lsb) == Q::min());       // -(2^m - 0.5) ties away to -2^m
    REQUIRE(Q::from_double_trunc(-top + 0.5 * lsb) == wrapping_add(Q::min(), Q::lsb()));
  }
}

TEMPLATE_TEST_CASE("q to_double is exact up to 53 bits and round-trips", "[q]", Q_TEST_FORMATS) {
  using Q = TestType;
  std::mt19937_64 rng(0x5EED0003u);
  for (int i = 0; i < 20000; ++i) {
    const auto r = ref::random_raw<Q>(rng);
    const Q x = Q::from_raw(r);
    const long double exact = std::ldexp(static_cast<long double>(r), -Q::frac_bits);
    if (Q::magnitude_bits <= 53) {
      REQUIRE(static_cast<long double>(x.to_double()) == exact);
      REQUIRE(Q::from_double(x.to_double()) == x);
    } else {
      REQUIRE(std::fabs(static_cast<long double>(x.to_double()) - exact) <= std::fabs(exact) * 0x1p-53L);
    }
    if (Q::magnitude_bits <= 24) REQUIRE(Q::from_float(x.to_float()) == x);
  }
}

TEMPLATE_TEST_CASE("q_cast between formats is rounded and saturating", "[q]", Q_TEST_FORMATS) {
  std::mt19937_64 rng(0x5EED0004u);
  check_cast_to_all<TestType>(rng);
}
