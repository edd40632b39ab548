// isqrt and isqrt_rounded (isqrt.hpp): the floor and the nearest integer square
// root, checked by their defining inequalities in exact 128-bit arithmetic.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>

#include "fixedpoint/isqrt.hpp"

namespace {

using u128 = unsigned __int128;

void require_floor_root(std::uint64_t x) {
  const fixedpoint::SquareRoot r = fixedpoint::isqrt(x);
  const u128 s = r.floor;
  INFO("x " << x);
  REQUIRE(s * s <= x);
  REQUIRE((s + 1) * (s + 1) > x);
  REQUIRE(r.remainder == x - r.floor * static_cast<std::uint64_t>(r.floor));
  // Nearest: (2s - 1)^2 <= 4x <= (2s + 1)^2, i.e. |s - sqrt(x)| <= 1/2 (equality is impossible: 4x is even).
  const u128 nearest = fixedpoint::isqrt_rounded(x);
  const u128 four_x = static_cast<u128>(x) * 4;
  if (nearest > 0) REQUIRE((2 * nearest - 1) * (2 * nearest - 1) < four_x);
  REQUIRE((2 * nearest + 1) * (2 * nearest + 1) > four_x);
}

}  // namespace

TEST_CASE("isqrt is the floor square root, isqrt_rounded the nearest", "[isqrt]") {
  for (std::uint64_t x = 0; x < (1u << 16); ++x) require_floor_root(x);
  std::mt19937_64 rng(20240622);
  for (int i = 0; i < (1 << 16); ++i) {
    const std::uint64_t x = rng() >> (rng() % 64);
    require_floor_root(x);
    // Squares, their neighbours and the half-way points between squares.
    const std::uint64_t s = x >> 32;
    for (const std::uint64_t y : {s * s, s * s - 1, s * s + 1, s * s + s, s * s + s + 1}) require_floor_root(y);
  }
  require_floor_root(UINT64_MAX);
  require_floor_root(UINT64_MAX - 1);
  require_floor_root(std::uint64_t{0xFFFFFFFF} * 0xFFFFFFFF);
}
