// normalize (normalize.hpp) against the exact direction in long double: within
// 1 unit of 2^-30 per component for inputs below 2^32, 1.87 for any int64 input
// whose squares the caller keeps meaningful (the pose builders' cross products reach 2^62).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>

#include "fixedpoint/normalize.hpp"

namespace {

using fixedpoint::Vec3Wide;

void require_within(const Vec3Wide& v, double bound_units) {
  const fixedpoint::Vec3Q30 u = fixedpoint::normalize(v);
  const long double x = static_cast<long double>(v.x), y = static_cast<long double>(v.y), z = static_cast<long double>(v.z);
  const long double length = std::sqrt(x * x + y * y + z * z);
  const long double unit = std::ldexp(1.0L, -30);
  INFO("v (" << v.x << ", " << v.y << ", " << v.z << ")");
  REQUIRE(std::fabs(u.x * unit - x / length) <= bound_units * unit);
  REQUIRE(std::fabs(u.y * unit - y / length) <= bound_units * unit);
  REQUIRE(std::fabs(u.z * unit - z / length) <= bound_units * unit);
}

std::int64_t random_component(std::mt19937_64& rng, int bits) {
  const auto magnitude = static_cast<std::int64_t>(rng() >> (64 - bits));
  return (rng() & 1) ? -magnitude : magnitude;
}

}  // namespace

TEST_CASE("normalize is within its bound for narrow and wide inputs", "[normalize]") {
  std::mt19937_64 rng(20240627);
  for (int i = 0; i < 200000; ++i) {
    const int bits = 1 + static_cast<int>(rng() % 32);  // |components| < 2^32
    // One component may be much smaller than the others, as in near-axis directions.
    const Vec3Wide v{random_component(rng, bits), random_component(rng, bits), random_component(rng, 1 + static_cast<int>(rng() % bits))};
    if (v.x == 0 && v.y == 0 && v.z == 0) continue;
    require_within(v, fixedpoint::normalize_error_narrow_input);
  }
  for (int i = 0; i < 200000; ++i) {
    const int bits = 33 + static_cast<int>(rng() % 30);  // up to 2^62
    require_within({random_component(rng, bits), random_component(rng, bits), random_component(rng, 1 + static_cast<int>(rng() % bits))},
                   fixedpoint::normalize_error_wide_input);
  }
}

TEST_CASE("normalize of an axis is exact, and of zero is zero", "[normalize]") {
  const std::int32_t one = 1 << 30;
  for (const std::int64_t scale : {std::int64_t{1}, std::int64_t{3}, std::int64_t{1} << 31, (std::int64_t{1} << 62) - 1}) {
    const fixedpoint::Vec3Q30 x = fixedpoint::normalize({scale, 0, 0}), y = fixedpoint::normalize({0, -scale, 0});
    REQUIRE((x.x == one && x.y == 0 && x.z == 0));
    REQUIRE((y.x == 0 && y.y == -one && y.z == 0));
  }
  const fixedpoint::Vec3Q30 zero = fixedpoint::normalize({0, 0, 0});
  REQUIRE((zero.x == 0 && zero.y == 0 && zero.z == 0));
}
