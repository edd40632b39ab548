// The span stage's arithmetic on its own (3_span/segments.hpp) and the small
// triangles' (2_triangle/small.hpp):
// * SegmentPlanner's closed-form segment lengths keep the quadratic through a
//   segment's exact start, middle and end within 2^-T texel of the true
//   perspective curve at every pixel (the bound (1) of segments.hpp), in double;
// * quadratic_steps' forward differences give that quadratic exactly when the
//   scale has room, else within the stated 2^(2k-1) units over 2^k pixels;
// * QuadraticAttribute::at gives the small triangle's quadratic exactly (mod 2^32);
// * the small triangle's barycentric planes stay within their derived bound of
//   the exact E_i / D at every pixel of the box;
// * the small triangle's quadratic uv stays within 2^-T texel of the exact
//   perspective value at every pixel it covers, wherever quadratic_enough lets
//   the triangle take the small path.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

#include "spanlight/2_triangle/small.hpp"
#include "spanlight/3_span/segments.hpp"

namespace {

// The true value along a span from a to b (exact ends f_a = 0, f_b = F texels):
// f(x) = F gamma(x), gamma = (x - a) e_b / ((b - x) e_a + (x - a) e_b).
double curve(double x, double a, double b, double e_a, double e_b, double F) {
  const double den = (b - x) * e_a + (x - a) * e_b;
  return F * (x - a) * e_b / den;
}

}  // namespace

TEST_CASE("SegmentPlanner's segments keep the quadratic through each segment's ends and middle within 2^-T texel",
          "[span][segments]") {
  // Random spans: length up to 2000 px, divisors 2^16..2^31 (up to 2^15 apart:
  // strong perspective), texel deltas up to 2^12 texels, every tolerance. The
  // planner picks each segment's length from the start column as walk.hpp does
  // (cut to fit before the span's end); the quadratic through the three exact
  // points is compared with the curve at every pixel of the segment.
  std::mt19937_64 random(0x5e6e07);
  const int spans = 4000;
  long long segments = 0, longer = 0, over = 0;
  double worst_ratio = 0.0;
  for (int n = 0; n < spans; ++n) {
    const std::int32_t a = static_cast<std::int32_t>(random() % 3000), length = 1 + static_cast<std::int32_t>(random() % 2000);
    const std::int32_t b = a + length;
    auto divisor = [&] { return static_cast<std::uint32_t>(std::ldexp(1.0, 16 + static_cast<int>(random() % 15)) * (1.0 + static_cast<double>(random() % 1000) / 1000.0)); };
    const std::uint32_t e_a = divisor(), e_b = divisor();
    const double F = std::ldexp(static_cast<double>(random() % 4096 + 1), -static_cast<int>(random() % 12)) * (random() % 2 ? 1 : -1);
    const auto delta8 = static_cast<std::uint64_t>(std::floor(std::fabs(F) * 256.0));  // as texel_delta8 (walk.hpp): floored
    const int tolerance = 1 + static_cast<int>(random() % 10);
    spanlight::SegmentPlanner planner{};
    planner.start(a, b, e_a, e_b, delta8, 24, tolerance, 6);
    const double limit = std::ldexp(1.0, -tolerance);
    for (std::int32_t x = a; x < b;) {
      int k = planner.length_log2_at(x);
      while ((std::int32_t{1} << k) > b - x) --k;
      const std::int32_t L = std::int32_t{1} << k;
      ++segments;
      longer += k > 0;
      if (k > 0) {
        const double h = L / 2.0;
        const double f0 = curve(x, a, b, e_a, e_b, F), f1 = curve(x + h, a, b, e_a, e_b, F), f2 = curve(x + L, a, b, e_a, e_b, F);
        for (std::int32_t j = 1; j < L; ++j) {
          if (j == L / 2) continue;
          const double t = j / h;  // Newton form through 0, 1, 2
          const double q = f0 + (f1 - f0) * t + (f2 - 2 * f1 + f0) / 2.0 * t * (t - 1.0);
          const double err = std::fabs(curve(x + j, a, b, e_a, e_b, F) - q);
          worst_ratio = std::max(worst_ratio, err / limit);
          if (err > limit) {
            ++over;
            UNSCOPED_INFO("span " << a << ".." << b << ", e " << e_a << " " << e_b << ", F " << F << ", T " << tolerance
                                  << ": segment at " << x << " of " << L << " px is off by " << err << " texel at +" << j);
          }
        }
      }
      x += L;
    }
  }
  std::printf("SegmentPlanner: %lld segments, %lld longer than one pixel, worst error / 2^-T %.3f\n", segments, longer,
              worst_ratio);
  INFO(segments << " segments, " << longer << " longer than a pixel, worst error / tolerance " << worst_ratio);
  CHECK(over == 0);
  CHECK(longer > segments / 4);  // not vacuous: the planner does take long segments
}

TEST_CASE("SegmentPlanner takes the longest allowed segment where nothing is to bound, and the rounding cap",
          "[span][segments]") {
  spanlight::SegmentPlanner p{};
  p.start(0, 1000, 1u << 30, 1u << 30, 1000 * 256, 24, 5, 6);  // equal divisors: affine, any length
  CHECK(p.length_log2_at(0) == 6);
  p.start(0, 1000, 1u << 30, 1u << 20, 0, 24, 5, 6);  // nothing changes along the span
  CHECK(p.length_log2_at(500) == 6);
  // Rounding: 2^(2k-1) units <= 2^-(T+1) texel needs 2k <= texel_bits - T: 8 bits a texel at T 2 caps k at 3.
  p.start(0, 1000, 1u << 30, 1u << 30, 1000 * 256, 8, 2, 6);
  CHECK(p.length_log2_at(0) == 3);
  // Strong perspective and a tight tolerance: shorter than the knob where den is smallest (near b).
  p.start(0, 1000, 1u << 30, 1u << 16, 4096 * 256, 24, 10, 6);
  int shortest = 6;
  for (std::int32_t x = 0; x < 1000; ++x) shortest = std::min(shortest, p.length_log2_at(x));
  CHECK(shortest < 6);
}

TEST_CASE("quadratic_steps gives the quadratic through the three points exactly with room, else within 2^(2k-1) units",
          "[span][segments]") {
  std::independent_bits_engine<std::mt19937, 32, std::uint32_t> random(0x9adc);  // 32-bit results: the same sequence
  std::uniform_int_distribution<std::int32_t> difference(-(1 << 30) + 1, (1 << 30) - 1), small_difference(-5000, 5000);
  long long checked = 0, wrong = 0;
  for (int n = 0; n < 20000; ++n) {
    const int k = 1 + static_cast<int>(random() % 6), shift = static_cast<int>(random() % 21);
    const bool small = n % 2 == 0;
    const std::int32_t d1 = small ? small_difference(random) : difference(random);
    const std::int32_t d2 = small ? small_difference(random) : difference(random);
    const spanlight::QuadraticSteps q = spanlight::quadratic_steps(d1, d2, k, shift);
    // Exactly, q(j) 2^(2k-1) = j d1 2^k + j (j - h)(d2 - d1), h = 2^(k-1); in the scale, times 2^shift.
    const int s = 2 * k - 1;
    const __int128 h = __int128{1} << (k - 1);
    std::uint32_t value = 0, step = q.step;
    for (std::int32_t j = 0; j <= (1 << k); ++j) {
      const __int128 exact = (__int128{j} * d1 * (__int128{1} << k) + __int128{j} * (j - h) * (__int128{d2} - d1)) *
                             (__int128{1} << shift);  // * 2^s
      const auto floor_low = static_cast<std::uint32_t>(static_cast<std::uint64_t>(exact >> s));  // floor, mod 2^32
      const __int128 below = exact - (exact >> s) * (__int128{1} << s);  // in [0, 2^s)
      const __int128 error = __int128{static_cast<std::int32_t>(value - floor_low)} * (__int128{1} << s) - below;  // * 2^s
      const __int128 bound = shift >= s ? 0 : __int128{1} << (2 * k - 1 + s);
      ++checked;
      wrong += error > bound || error < -bound;
      value += step;
      step += q.curve;
    }
  }
  INFO(checked << " stepped values checked");
  CHECK(wrong == 0);
}

TEST_CASE("QuadraticAttribute::at gives a small triangle's quadratic exactly at any row and column, modulo 2^32", "[span][small]") {
  std::independent_bits_engine<std::mt19937, 32, std::uint32_t> random(0x5a11);  // 32-bit results: the same sequence
  int wrong = 0;
  for (int n = 0; n < 200; ++n) {
    const spanlight::QuadraticAttribute q{random(), random(), random(), random(), random(), random()};
    for (std::uint32_t r = random() % 64; r < 64; ++r) {
      for (const std::uint32_t c0 : {0u, 1u, 17u, 63u}) {
        std::uint32_t v, step;
        q.at(r, c0, v, step);
        const std::uint32_t curve = q.curve();
        for (std::uint32_t c = c0; c < 64; ++c) {  // the kernel steps on from c0
          const std::uint32_t exact = q.q00 + q.q10 * c + q.q01 * r + q.q20 * c * c + q.q11 * c * r + q.q02 * r * r;
          wrong += v != exact;
          v += step;
          step += curve;
        }
      }
    }
  }
  CHECK(wrong == 0);
}

namespace {

struct PlaneErrors {
  long long triangles = 0, values = 0, over = 0;
  double worst_units = 0.0, worst_ratio = 0.0;
};

// Each plane coefficient is floor(x rcp / 2^(4 + L)) with rcp = reciprocal<8, 2> of D: off by less than
// one unit (the floor) plus |exact| eps (eps = 2^-28.9, |exact| <= 24 * 2^26 for non-slivers). A value at
// column c, row r sums 1 + c + r coefficients: |error| <= (1 + c + r)(1 + 24 * 2^26 * 2^-28.9) units of 2^-26.
PlaneErrors plane_errors() {
  std::independent_bits_engine<std::mt19937, 32, std::uint32_t> random(0x5ba11);  // 32-bit results: the same sequence
  const double eps = std::ldexp(1.0, -28) / std::sqrt(std::sqrt(std::sqrt(2.0))) /* 2^-28.125 > 2^-28.9: safe */;
  PlaneErrors r;
  const int cases = 3000;
  for (int n = 0; n < cases; ++n) {
    spanlight::ScreenVertex v[3]{};
    const std::int32_t extent = 256 + static_cast<std::int32_t>(random() % (spanlight::small_triangle_extent - 256));
    for (auto& s : v) {
      s.x = 100000 + static_cast<std::int32_t>(random() % static_cast<std::uint32_t>(extent));
      s.y = 3000 + static_cast<std::int32_t>(random() % static_cast<std::uint32_t>(extent));
    }
    spanlight::SmallTriangle t{};
    bool covers = false;
    if (!spanlight::setup_small(v, spanlight::Cull::none, 1 << 14, t, covers) || !covers) continue;
    ++r.triangles;
    // The exact barycentrics from the triangle's own vertices, in setup order (slot 1, slot 2).
    const std::int32_t ox = t.column0 * 256 + 128, oy = t.row0 * 256 + 128;
    const spanlight::ScreenVertex& p0 = v[t.order[0]];
    const spanlight::ScreenVertex& p1 = v[t.order[1]];
    const spanlight::ScreenVertex& p2 = v[t.order[2]];
    const double D = double(p1.x - p0.x) * double(p2.y - p0.y) - double(p1.y - p0.y) * double(p2.x - p0.x);
    auto exact = [&](const spanlight::ScreenVertex& a, const spanlight::ScreenVertex& b, double x, double y) {
      // E for the edge from a to b at (x, y), as SmallEdge: dy * (ax - x) - dx * (ay - y), over D.
      const double dx = b.x - a.x, dy = b.y - a.y;
      return (dy * (a.x - x) - dx * (a.y - y)) / D;
    };
    for (std::int32_t row = 0; row < 64; ++row) {
      for (std::int32_t c = 0; c < 64; ++c) {
        const double x = ox + 256.0 * c, y = oy + 256.0 * row;
        // Plane l1 is edge 1 (slot 2 -> slot 0), l2 edge 2 (slot 0 -> slot 1), as setup_small orders them.
        const double l1 = exact(p2, p0, x, y), l2 = exact(p0, p1, x, y);
        if (std::fabs(l1) > 12.0 || std::fabs(l2) > 12.0) continue;
        const double got1 = t.l1.at_corner + double(t.l1.per_column) * c + double(t.l1.per_row) * row;
        const double got2 = t.l2.at_corner + double(t.l2.per_column) * c + double(t.l2.per_row) * row;
        const double bound = (1 + c + row) * (1.0 + 24.0 * 0x1p26 * eps);
        for (const double e : {std::fabs(got1 - l1 * 0x1p26), std::fabs(got2 - l2 * 0x1p26)}) {
          ++r.values;
          r.worst_units = std::max(r.worst_units, e);
          r.worst_ratio = std::max(r.worst_ratio, e / bound);
          r.over += e > bound;
        }
      }
    }
  }
  return r;
}

}  // namespace

TEST_CASE("a small triangle's barycentric planes stay within their derived bound of E_i / D over its box",
          "[span][small]") {
  const PlaneErrors r = plane_errors();
  std::printf("small triangles: %lld set up, %lld plane values, worst %.2f units of 2^-26 (error / bound %.3f)\n",
              r.triangles, r.values, r.worst_units, r.worst_ratio);
  INFO(r.triangles << " small triangles, worst plane error " << r.worst_units << " units of 2^-26");
  CHECK(r.triangles > 1000);
  CHECK(r.over == 0);
}

TEST_CASE("a small triangle's barycentric planes stay within small.hpp's stated 130 * 2^-27 over the box",
          "[span][small]") {
  // small.hpp (SmallTriangle::affine) states the planes' rounding at 2^-27 a step, 130 * 2^-27 over
  // the box (65 units of 2^-26), and draw.hpp's small_depth_margin (256 Q0.32 units) is derived from
  // it. The coefficients are rounded, within half a unit (2^-27) each, and the box's corner sums
  // 129 of them. Measured here against the exact E_i / D.
  const PlaneErrors r = plane_errors();
  INFO("worst plane error " << r.worst_units << " units of 2^-26; small.hpp states at most 65");
  CHECK(r.worst_units <= 65.0);
}

namespace {

struct QuadraticErrors {
  long long triangles = 0, pixels = 0, over = 0;
  double worst_ratio = 0.0;  // error / 2^-T texel
};

// Random small triangles with perspective weights up to 1/32 apart and uv ranges from a
// texel to 2^17 texels, walked as draw_small walks them (setup_small's edges, one
// QuadraticAttribute a coordinate), against u = sum l_k u_k W_k / sum l_k W_k in double.
QuadraticErrors quadratic_errors(int tolerance_log2) {
  std::independent_bits_engine<std::mt19937, 32, std::uint32_t> random(0x9a0d + tolerance_log2);
  constexpr int frac = 8;
  QuadraticErrors r;
  for (int n = 0; n < 4000; ++n) {
    // A repeating texture of 256 or 4096 texels a side: 2^24 or 2^20 step units a texel.
    const int texel_bits = n % 2 == 0 ? 24 : 20, shift = texel_bits - frac;
    spanlight::ScreenVertex v[3]{};
    const std::int32_t extent = 256 + static_cast<std::int32_t>(random() % (spanlight::small_triangle_extent - 256));
    const std::int32_t range_max = std::int32_t{1} << (8 + random() % 18);  // exact units: 1 to 2^17 texels
    std::int32_t uv[3][2];
    for (int k = 0; k < 3; ++k) {
      v[k].x = 100000 + static_cast<std::int32_t>(random() % static_cast<std::uint32_t>(extent));
      v[k].y = 3000 + static_cast<std::int32_t>(random() % static_cast<std::uint32_t>(extent));
      v[k].inv_w_mantissa = (1u << 30) + random() % (1u << 25);  // within 2^25 / 2^30 = 1/32 of each other
      v[k].inv_w_exponent = 40;
      for (auto& c : uv[k]) c = static_cast<std::int32_t>(random() % static_cast<std::uint32_t>(range_max));
    }
    spanlight::SmallTriangle t{};
    bool covers = false;
    if (!spanlight::setup_small(v, spanlight::Cull::none, 1 << 14, t, covers) || !covers) continue;
    std::int32_t range = 0;
    for (int c = 0; c < 2; ++c) {
      const auto [lo, hi] = std::minmax({uv[0][c], uv[1][c], uv[2][c]});
      range = std::max(range, hi - lo);
    }
    spanlight::PerspectiveWeights w{};
    if (!spanlight::perspective_weights_of(v, w) || !spanlight::quadratic_enough(w, range, frac, texel_bits, tolerance_log2)) continue;
    ++r.triangles;
    // As draw_small: e's plane, then one quadratic a coordinate, from the first row.
    const int i0 = t.order[0], i1 = t.order[1], i2 = t.order[2];
    const spanlight::AffineAttribute e = t.affine(w.e[i0] >> 1, (w.e[i1] >> 1) - (w.e[i0] >> 1), (w.e[i2] >> 1) - (w.e[i0] >> 1), 0);
    spanlight::QuadraticAttribute quadratic[2];
    for (int c = 0; c < 2; ++c) {
      const auto base = static_cast<std::uint32_t>(uv[i0][c]) << shift;
      quadratic[c] = spanlight::perspective_quadratic(t, base, shift, range, uv[i1][c] - uv[i0][c], w.e[i1],
                                                      uv[i2][c] - uv[i0][c], w.e[i2], e);
    }
    const double area = double(v[1].x - v[0].x) * double(v[2].y - v[0].y) - double(v[1].y - v[0].y) * double(v[2].x - v[0].x);
    auto lambda = [&](int k, double x, double y) {  // the screen barycentric of vertex k
      const spanlight::ScreenVertex &a = v[(k + 1) % 3], &b = v[(k + 2) % 3];
      return ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x)) / area;
    };
    for (std::int32_t row = t.row_begin; row < t.row_end; ++row) {
      std::int32_t lo = -1000, hi = 1000;
      if (t.columns(lo, hi)) {
        for (std::int32_t c = lo; c <= hi; ++c) {
          const double x = (t.column0 + c) * 256.0 + 128, y = row * 256.0 + 128;
          double num[2] = {0, 0}, den = 0;
          for (int k = 0; k < 3; ++k) {
            const double weight = lambda(k, x, y) * v[k].inv_w_mantissa;
            den += weight;
            for (int q = 0; q < 2; ++q) num[q] += weight * uv[k][q];
          }
          ++r.pixels;
          for (int q = 0; q < 2; ++q) {
            std::uint32_t value, step;
            quadratic[q].at(static_cast<std::uint32_t>(row - t.row0), static_cast<std::uint32_t>(c), value, step);
            // The difference modulo the texture's wrap (2^32 step units), in texels.
            const double exact_units = std::fmod(num[q] / den * std::ldexp(1.0, shift), 0x1p32);
            const double diff = std::ldexp(std::remainder(double(value) - exact_units, 0x1p32), -texel_bits);
            const double ratio = std::fabs(diff) * std::ldexp(1.0, tolerance_log2);
            r.worst_ratio = std::max(r.worst_ratio, ratio);
            r.over += ratio > 1.0;
          }
        }
      }
      t.next_row();
    }
  }
  return r;
}

}  // namespace

TEST_CASE("a small triangle's quadratic uv stays within 2^-T texel of the perspective value wherever it is allowed",
          "[span][small]") {
  for (const int tolerance_log2 : {3, 5, 7}) {
    const QuadraticErrors r = quadratic_errors(tolerance_log2);
    std::printf("T = %d: %lld small triangles allowed, %lld pixels, worst error %.3f of 2^-T texel\n", tolerance_log2,
                r.triangles, r.pixels, r.worst_ratio);
    INFO("T = " << tolerance_log2 << ": " << r.triangles << " triangles, worst error " << r.worst_ratio << " of 2^-T");
    CHECK(r.triangles > 200);
    CHECK(r.over == 0);
  }
}

TEST_CASE("divide_by_48 is x / 48 for every x of its range", "[span]") {
  int wrong = 0;
  for (int x = 0; x < (1 << 16); ++x) wrong += spanlight::divide_by_48(x) != x / 48;
  REQUIRE(wrong == 0);
  // Beyond the range the product overflows and the multiplier's excess shows (why log2_for
  // clamps before dividing).
  int beyond = 0;
  for (int x = 1 << 17; x < (1 << 17) + 4096; ++x) beyond += spanlight::divide_by_48(x) != x / 48;
  REQUIRE(beyond > 0);
}
