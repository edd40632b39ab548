// vec.hpp: transform against an exact __int128 reference inside the stated bounds
// (|entries| < 2^29, |coords| < 2^30, plus the full int32 range the header
// proves), and mat4_block_from_doubles' choice of exponent and rounding.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>

#include "fixedpoint/vec.hpp"

namespace {

using fixedpoint::Mat4Block;
using fixedpoint::Vec3Q16;
using fixedpoint::Vec4Wide;
using i128 = __int128;

#if defined(__SANITIZE_ADDRESS__)
constexpr int random_cases = 1 << 14;
#else
constexpr int random_cases = 1 << 17;
#endif

// Exact row value in Q(frac_bits + 16), rescaled to Q32 with ties away from zero,
// and saturated to +-INT64_MAX (only reachable by left shifts, frac_bits < 16).
std::int64_t reference_row(const Mat4Block& a, int row, const Vec3Q16& v) {
  const i128 sum = static_cast<i128>(a.m[row]) * v.x + static_cast<i128>(a.m[4 + row]) * v.y +
                   static_cast<i128>(a.m[8 + row]) * v.z + static_cast<i128>(a.m[12 + row]) * 65536;
  const int shift = a.frac_bits + 16 - 32;
  i128 r = 0;
  if (shift >= 0) {
    const i128 mag = sum < 0 ? -sum : sum;
    const i128 rounded = shift == 0 ? mag : (mag + (static_cast<i128>(1) << (shift - 1))) >> shift;
    r = sum < 0 ? -rounded : rounded;
  } else {
    r = sum * (static_cast<i128>(1) << -shift);
  }
  if (r > INT64_MAX) return INT64_MAX;
  if (r < -INT64_MAX) return -INT64_MAX;
  return static_cast<std::int64_t>(r);
}

std::int32_t random_in(std::mt19937_64& rng, std::int64_t limit) {  // uniform in (-limit, limit)
  return static_cast<std::int32_t>(static_cast<std::int64_t>(rng() % static_cast<std::uint64_t>(2 * limit - 1)) - (limit - 1));
}

Mat4Block random_matrix(std::mt19937_64& rng) {
  Mat4Block a{};
  for (std::int32_t& m : a.m) m = random_in(rng, fixedpoint::mat4_block_entry_limit);
  a.frac_bits = static_cast<int>(rng() % 61u);
  return a;
}

void require_matches_reference(const Mat4Block& a, const Vec3Q16& v) {
  const Vec4Wide out = fixedpoint::transform(a, v);
  INFO("frac_bits=" << a.frac_bits << " v=(" << v.x << ", " << v.y << ", " << v.z << ")");
  REQUIRE(out.x == reference_row(a, 0, v));
  REQUIRE(out.y == reference_row(a, 1, v));
  REQUIRE(out.z == reference_row(a, 2, v));
  REQUIRE(out.w == reference_row(a, 3, v));
}

}  // namespace

TEST_CASE("transform is the exact sum rounded once", "[vec]") {
  std::mt19937_64 rng(0x5EED0020u);
  for (int i = 0; i < random_cases; ++i) {
    const Mat4Block a = random_matrix(rng);
    const std::int64_t coord_limit = (i % 2 == 0) ? (std::int64_t{1} << 30) : (std::int64_t{1} << 31);
    const Vec3Q16 v{random_in(rng, coord_limit), random_in(rng, coord_limit), random_in(rng, coord_limit)};
    require_matches_reference(a, v);
  }
}

TEST_CASE("transform at the extreme entries and coordinates", "[vec]") {
  const std::int32_t e = fixedpoint::mat4_block_entry_limit - 1;
  for (const int frac_bits : {0, 15, 16, 17, 32, 48, 60}) {
    for (const std::int32_t sign : {1, -1}) {
      Mat4Block a{};
      for (std::int32_t& m : a.m) m = sign * e;
      a.frac_bits = frac_bits;
      require_matches_reference(a, Vec3Q16{INT32_MAX, INT32_MAX, INT32_MAX});
      require_matches_reference(a, Vec3Q16{INT32_MIN, INT32_MIN, INT32_MIN});
      require_matches_reference(a, Vec3Q16{INT32_MIN, INT32_MAX, 0});
      // Ties away from zero make the linear part odd: without translation,
      // transform(a, -v) = -transform(a, v) exactly.
      a.m[12] = a.m[13] = a.m[14] = a.m[15] = 0;
      const Vec3Q16 v{12345, -678901, 1 << 29};
      const Vec4Wide p = fixedpoint::transform(a, v);
      const Vec4Wide n = fixedpoint::transform(a, Vec3Q16{-v.x, -v.y, -v.z});
      REQUIRE(p.x == -n.x);
      REQUIRE(p.w == -n.w);
    }
  }
}

TEST_CASE("mat4_block_from_doubles picks the largest exponent below 2^29", "[vec]") {
  SECTION("identity and translation") {
    const double m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 3.5, -2.25, 10, 1};  // column-major, translation last
    const Mat4Block a = fixedpoint::mat4_block_from_doubles(m);
    REQUIRE(a.frac_bits == 25);  // max |entry| = 10 < 16: 10 * 2^25 < 2^29 <= 10 * 2^26
    REQUIRE(fixedpoint::mat4_block_entry(a, 3, 0) == 3.5);
    REQUIRE(fixedpoint::mat4_block_entry(a, 3, 1) == -2.25);
    const Vec4Wide out = fixedpoint::transform(a, fixedpoint::vec3_q16(1.0, 2.0, -0.5));
    REQUIRE(out.x == static_cast<std::int64_t>(4.5 * 4294967296.0));
    REQUIRE(out.y == static_cast<std::int64_t>(-0.25 * 4294967296.0));
    REQUIRE(out.z == static_cast<std::int64_t>(9.5 * 4294967296.0));
    REQUIRE(out.w == std::int64_t{1} << 32);
  }
  SECTION("random matrices: bound kept, largest entry uses 29 bits, entries rounded to nearest") {
    std::mt19937_64 rng(0x5EED0021u);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
      double m[16];
      const double scale = std::ldexp(1.0, static_cast<int>(rng() % 60u) - 30);
      for (double& x : m) x = unit(rng) * scale;
      const Mat4Block a = fixedpoint::mat4_block_from_doubles(m);
      std::int32_t largest = 0;
      for (int k = 0; k < 16; ++k) {
        const std::int32_t mk = a.m[k] < 0 ? -a.m[k] : a.m[k];
        REQUIRE(mk < fixedpoint::mat4_block_entry_limit);
        if (mk > largest) largest = mk;
        const long double exact = std::ldexp(static_cast<long double>(m[k]), a.frac_bits);
        REQUIRE(std::fabs(static_cast<long double>(a.m[k]) - exact) <= 0.5L);
      }
      REQUIRE(a.frac_bits >= 0);
      REQUIRE(a.frac_bits <= fixedpoint::mat4_block_max_frac_bits);
      if (a.frac_bits < fixedpoint::mat4_block_max_frac_bits) REQUIRE(largest >= (1 << 28));
    }
  }
  SECTION("zero, tiny, huge and NaN entries") {
    const double zeros[16] = {};
    REQUIRE(fixedpoint::mat4_block_from_doubles(zeros).frac_bits == 60);
    double huge[16] = {};
    huge[0] = 1e12;
    huge[5] = -1e12;
    huge[1] = std::nan("");
    const Mat4Block h = fixedpoint::mat4_block_from_doubles(huge);
    REQUIRE(h.frac_bits == 0);
    REQUIRE(h.m[0] == fixedpoint::mat4_block_entry_limit - 1);
    REQUIRE(h.m[5] == -(fixedpoint::mat4_block_entry_limit - 1));
    REQUIRE(h.m[1] == 0);
  }
  static_assert(fixedpoint::mat4_block_from_doubles({2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1}).frac_bits == 27);
}
