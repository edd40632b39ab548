// trig.hpp: the polynomial kernels within their truncation bounds, sin_cos within
// its stated 0.93 * 2^-30, exact at the quarter turns, and the degree conversions.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>

#include "fixedpoint/trig.hpp"

namespace {

using fixedpoint::Turns;

constexpr long double pi = 3.141592653589793238462643383279502884L;

long double angle_radians(Turns a) { return static_cast<long double>(a.raw) * (2 * pi) / 4294967296.0L; }

void require_sin_cos_within_bound(Turns a) {
  const fixedpoint::SinCos sc = fixedpoint::sin_cos(a);
  const long double unit = std::ldexp(1.0L, -30);
  const long double x = angle_radians(a);
  INFO("raw " << a.raw);
  REQUIRE(std::fabs(sc.sin * unit - std::sin(x)) <= fixedpoint::sin_cos_error * unit);
  REQUIRE(std::fabs(sc.cos * unit - std::cos(x)) <= fixedpoint::sin_cos_error * unit);
}

}  // namespace

TEST_CASE("the sine and cosine kernels are within their truncation bounds for every w they take", "[trig]") {
  std::mt19937_64 rng(20240623);
  const auto w_max = static_cast<std::uint32_t>(std::ldexp(0.6169, 31));  // (pi/4)^2 = 0.61685
  for (int i = 0; i < 100000; ++i) {
    const auto w_q31 = static_cast<std::int32_t>(rng() % (w_max + 1));
    const long double w = std::ldexp(static_cast<long double>(w_q31), -31), z = std::sqrt(w);
    const long double s = z == 0 ? 1.0L : std::sin(z) / z;
    INFO("w " << w_q31);
    REQUIRE(std::fabs(std::ldexp(static_cast<long double>(fixedpoint::detail::sin_over_z_q60(w_q31)), -60) - s) <=
            fixedpoint::detail::sin_over_z_kernel_error);
    REQUIRE(std::fabs(std::ldexp(static_cast<long double>(fixedpoint::detail::cos_q60(w_q31)), -60) - std::cos(z)) <=
            fixedpoint::detail::cos_kernel_error);
  }
}

TEST_CASE("sin_cos is within 0.93 * 2^-30 everywhere and exact at the quarter turns", "[trig]") {
  std::mt19937_64 rng(20240624);
  for (int i = 0; i < (1 << 18); ++i) require_sin_cos_within_bound(Turns{static_cast<std::uint32_t>(rng())});
  // Around every octant boundary, where the reduction switches between sine and cosine.
  for (std::uint32_t octant = 0; octant < 8; ++octant) {
    for (std::int64_t delta = -64; delta <= 64; ++delta) {
      require_sin_cos_within_bound(Turns{static_cast<std::uint32_t>((std::int64_t{octant} << 29) + delta)});
    }
  }
  const std::int32_t one = 1 << 30;
  REQUIRE(fixedpoint::sin_cos(Turns{0}).sin == 0);
  REQUIRE(fixedpoint::sin_cos(Turns{0}).cos == one);
  REQUIRE(fixedpoint::sin_cos(Turns{1u << 30}).sin == one);
  REQUIRE(fixedpoint::sin_cos(Turns{1u << 30}).cos == 0);
  REQUIRE(fixedpoint::sin_cos(Turns{2u << 30}).sin == 0);
  REQUIRE(fixedpoint::sin_cos(Turns{2u << 30}).cos == -one);
  REQUIRE(fixedpoint::sin_cos(Turns{3u << 30}).sin == -one);
  REQUIRE(fixedpoint::sin_cos(Turns{3u << 30}).cos == 0);
}

TEST_CASE("sin_cos keeps the symmetries of sine and cosine exactly", "[trig]") {
  std::mt19937_64 rng(20240625);
  for (int i = 0; i < 100000; ++i) {
    const auto raw = static_cast<std::uint32_t>(rng());
    const fixedpoint::SinCos a = fixedpoint::sin_cos(Turns{raw});
    const fixedpoint::SinCos negated = fixedpoint::sin_cos(Turns{0u - raw});
    const fixedpoint::SinCos half_turn = fixedpoint::sin_cos(Turns{raw + (1u << 31)});
    INFO("raw " << raw);
    REQUIRE(negated.sin == -a.sin);
    REQUIRE(negated.cos == a.cos);
    REQUIRE(half_turn.sin == -a.sin);
    REQUIRE(half_turn.cos == -a.cos);
  }
}

TEST_CASE("degrees convert to Turns rounded to nearest and wrapped, and back exactly", "[trig]") {
  REQUIRE(fixedpoint::turns_from_degrees(0).raw == 0);
  REQUIRE(fixedpoint::turns_from_degrees(90).raw == 1u << 30);
  REQUIRE(fixedpoint::turns_from_degrees(-90).raw == 3u << 30);
  REQUIRE(fixedpoint::turns_from_degrees(360).raw == 0);
  REQUIRE(fixedpoint::turns_from_degrees(720 + 180).raw == 1u << 31);
  REQUIRE(fixedpoint::degrees(Turns{1u << 29}) == 45.0);
  REQUIRE(fixedpoint::turns_from_degrees(1000 * 360 + 90).raw == 1u << 30);
  REQUIRE(fixedpoint::turns_from_degrees(1e300).raw == 0);
  REQUIRE(fixedpoint::turns_from_degrees(std::nan("")).raw == 0);
  std::mt19937_64 rng(20240626);
  for (int i = 0; i < 100000; ++i) {
    const Turns t{static_cast<std::uint32_t>(rng())};
    REQUIRE(fixedpoint::turns_from_degrees(fixedpoint::degrees(t)) == t);
    const double d = std::uniform_real_distribution<double>(0.0, 359.0)(rng);
    const double back = fixedpoint::degrees(fixedpoint::turns_from_degrees(d));
    REQUIRE(std::fabs(back - d) <= 0.5 * 360.0 / 4294967296.0 * (1 + 1e-9));
  }
}
