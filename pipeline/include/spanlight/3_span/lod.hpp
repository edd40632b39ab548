// Stage 3d, the mip level of a run (scene format 2, `trilinear` textures):
// lambda = log2 rho, rho the larger length of the two screen derivatives of
// (U, V) = uv in level-0 texels, taken exactly from the triangle's perspective
// mapping (docs/scene-format.md, "Mipmapped textures").
//
// With barycentrics l_i, perspective weights w_i (proportional to 1/w) and
// W = sum l_i w_i, u = sum l_i w_i u_i / W, and for each pair of vertices
// (i, k) with m the third,
//
//   dU/dx = sum_(i,k) w_i w_k (U_i - U_k) (y - y_m) / (2A W^2),
//   dU/dy = sum_(i,k) w_i w_k (U_i - U_k) (x_m - x) / (2A W^2)
//
// (the pair's l_i,x l_k - l_i l_k,x vanishes at vertex m and does not depend
// on x). So along a row the numerator of d/dx is constant and that of d/dy is
// affine in the column: per evaluation, a few products and two logarithms
// (d/dx's length is taken once a row).
//
// Along a row lambda is taken linear on pieces of up to 128 pixels (LodPiece),
// each ending at a pixel centre of the span (a span is one piece where lambda
// allows): its value at the piece's ends, the piece halved until lambda at its
// middle and quarters (exact points, in subpixels) lies within
// lod_chord_tolerance of the chord. Where lambda keeps the sign of
// its curvature on a piece, the chord's distance to it is at most twice its
// distance at the middle (a concave function zero at both ends is at most
// twice its middle value anywhere between). With e = 2^-10.4 the error of one
// evaluation (lod_q16_at), a pixel's lambda is within 2 (1/64 + 2e) (the chord
// of the exact ends) + e (its ends) + 2^-10 (the step's rounding) + 2^-9 (the
// mix weight's Q.8 rounding) < 0.038 of its own. The quarters are checked too,
// because lambda is the larger of two terms: where the larger changes inside a
// piece the curvature's sign changes, and a corner between check points can
// be cut by the chord beyond that bound (tests/mipmap: 1 pixel in 4,500 of its
// random triangles, by at most 0.16 of a level, which moves the colour by that
// fraction of the two levels' difference).
#pragma once

#include <algorithm>
#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/divide.hpp"
#include "spanlight/1_vertex/project.hpp"
#include "spanlight/2_triangle/attributes.hpp"
#include "spanlight/2_triangle/setup.hpp"

namespace spanlight {

// log2(1 + i/32) in Q.16, i = 0..32.
inline constexpr std::uint32_t log2_q16_table[33] = {
    0,     2909,  5732,  8473,  11136, 13727, 16248, 18704, 21098, 23433, 25711, 27936, 30109, 32234, 34312, 36346, 38336,
    40286, 42196, 44068, 45904, 47705, 49472, 51207, 52911, 54584, 56229, 57845, 59434, 60997, 62534, 64047, 65536};

// log2 x in Q.16 for x > 0: the leading bit, then the table, linear between
// its 1/32 steps. Linear interpolation of log2 over a step of 1/32 is within
// (1/32)^2 / (8 ln 2) = 2^-12.5 of it, the position's truncation adds 2^-16:
// |error| < 2^-12.3.
constexpr std::int32_t log2_q16(std::uint64_t x) {
  const int e = fixedpoint::bit_length_by_words(x) - 1;
  // The 32 bits after the leading one (x normalised to [2^32, 2^33), its low word), by
  // 32-bit shifts: (lo << 1) << (31 - e) is lo << (32 - e) without UB at e = 0.
  const std::uint32_t below = e >= 32 ? fixedpoint::low_word_shifted_right(x, e - 32)
                                      : (static_cast<std::uint32_t>(x) << 1) << (31 - e);
  const std::uint32_t i = below >> 27, within = (below >> 11) & 0xFFFFu;
  const std::uint32_t lo = log2_q16_table[i], hi = log2_q16_table[i + 1];
  return e * 65536 + static_cast<std::int32_t>(lo + (((hi - lo) * within) >> 16));  // (hi - lo) < 2^12
}

// log2 (a^2 + b^2) in Q.16: twice the log of the length of (a, b), a or b nonzero.
constexpr std::int32_t log2_length2_q16(std::int64_t a, std::int64_t b) {
  const std::uint64_t ua = static_cast<std::uint64_t>(a < 0 ? -a : a), ub = static_cast<std::uint64_t>(b < 0 ? -b : b);
  const std::uint64_t larger = ua > ub ? ua : ub;
  const int k = std::max(fixedpoint::bit_length_by_words(larger) - 31, 0);  // <= 33
  // < 2^31 each, by word shifts: the squares (32 x 32 products) sum below 2^63; relative error 2^-30.
  const std::uint32_t sa = fixedpoint::word_shifted_right(ua, k), sb = fixedpoint::word_shifted_right(ub, k);
  return log2_q16(fixedpoint::mul_u32(sa, sa) + fixedpoint::mul_u32(sb, sb)) + 2 * k * 65536;
}

// The triangle's part of lambda, for trilinear objects.
struct LodPlanes {
  // Numerators (times 2^-shift): d/dx = b y_s + ax (per row), d/dy = b x_s + ay (per column),
  // [0] for u and [1] for v; x_s, y_s the pixel centre in subpixels.
  std::int64_t b[2], ax[2], ay[2];
  int e_shift;               // H sums E_i >> e_shift (E_i < 2^31 then); below 13 (2A < 2^43)
  std::int32_t constant_q16; // twice the log of the constant factors (below), Q.16
  std::int32_t row_y;        // the current row's centre in subpixels (set_lod_row)
  std::int32_t along_x_q16;  // log2 of d/dx's squared length on that row (constant along it); INT32_MIN: zero
  std::int32_t last_level;   // the texture's level_count - 1 (the caller sets it)
};

struct NoLodPlanes {};  // in their place in a build without trilinear textures

// From the setup, its window vertices in setup order and the uv at them.
constexpr LodPlanes lod_planes(const TriangleSetup& t, const ScreenVertex* const (&v)[3], const std::int32_t (&u)[3],
                               const std::int32_t (&vv)[3], int uv_frac_bits) {
  LodPlanes p{};
  // The pairs (0, 1; m = 2), (1, 2; 0), (2, 0; 1): w_i w_k / 2^31 < 2^31, times u_i - u_k (< 2^31).
  std::int64_t pu[3], pv[3];
  std::uint64_t largest = 0;
  for (int m = 0; m < 3; ++m) {
    const int i = m == 2 ? 0 : m + 1, k = m == 0 ? 2 : m - 1;  // (m + 1) mod 3, (m + 2) mod 3: no divide on M0+
    const auto ww = static_cast<std::int64_t>(fixedpoint::mul_u32(t.omega[i], t.omega[k]) >> 31);
    pu[m] = ww * (std::int64_t{u[i]} - u[k]);
    pv[m] = ww * (std::int64_t{vv[i]} - vv[k]);
    for (const std::int64_t x : {pu[m], pv[m]}) {
      const std::uint64_t mag = static_cast<std::uint64_t>(x < 0 ? -x : x);
      largest = mag > largest ? mag : largest;
    }
  }
  // One shift brings every product below 2^36: times a coordinate (< 2^21 subpixels), three
  // terms stay below 2^59. The bits it drops are 2^-36 of the largest term.
  const int shift = std::max(fixedpoint::bit_length(largest) - 36, 0);
  for (int c = 0; c < 2; ++c) {
    const std::int64_t* pc = c == 0 ? pu : pv;
    p.b[c] = p.ax[c] = p.ay[c] = 0;
    for (int m = 0; m < 3; ++m) {
      const std::int64_t q = pc[m] >> shift;
      p.b[c] += q;
      p.ax[c] -= q * v[m]->y;
      p.ay[c] -= q * v[m]->x;
    }
  }
  const std::int64_t d = t.edge[0].value_at(0) + t.edge[1].value_at(0) + t.edge[2].value_at(0);  // 2 area, subpixel^2
  const int d_bits = fixedpoint::bit_length(static_cast<std::uint64_t>(d));
  p.e_shift = d_bits > 31 ? d_bits - 31 : 0;
  // lambda = log2 |G| 2^(shift + 31) 2^(8 - frac) D / (H 2^e_shift)^2, |G| = sqrt(length2), so
  // 2 lambda = log2 length2 + 2 (shift + 31 + 8 - frac - 2 e_shift) + 2 log2 D - 4 log2 H.
  p.constant_q16 = 2 * (shift + 31 + 8 - uv_frac_bits - 2 * p.e_shift) * 65536 + 2 * log2_q16(static_cast<std::uint64_t>(d));
  return p;
}

// The row whose pixel centres lod_q16_at evaluates: d/dx's numerator b y_s + ax
// is the same all along it, so its length's logarithm is taken once.
constexpr void set_lod_row(LodPlanes& p, std::int32_t row) {
  p.row_y = row * 256 + 128;
  // row_y >= 0: the products (which fit int64) without __muldi3 on ARMv6-M.
  const auto y = static_cast<std::uint32_t>(p.row_y);
  const std::int64_t xu = fixedpoint::mul_s64_u32(p.b[0], y) + p.ax[0], xv = fixedpoint::mul_s64_u32(p.b[1], y) + p.ax[1];
  p.along_x_q16 = xu == 0 && xv == 0 ? INT32_MIN : log2_length2_q16(xu, xv);
}

// lambda (Q.16) at column c of the current row: the larger derivative length over
// H^2, H = sum E_i w_i (each E_i >> e_shift <= 2^31 inside, times w_i < 2^31: the
// sum fits 64 bits unsigned; it is at least D w_min, so the dropped bits are
// 2^-30 w_max / w_min of it). Four Q.16 logarithms (2^-12.3 each, the length's
// counted half) and the halving: |error| < 3.5 * 2^-12.3 + 2^-17 < 2^-10.4
// against the exact lambda at that pixel centre.
inline constexpr std::int32_t lod_q16_zero = -(std::int32_t{256} << 16);  // rho = 0: magnified without end
// x_s: the point's x in subpixels on the current row (a pixel centre, or between two
// of a span's: E_i is exact there, slope / 256 per subpixel).
constexpr std::int32_t lod_q16_at_x(const LodPlanes& p, const TriangleSetup& t, std::int32_t x_s) {
  std::uint64_t h = 0;
  for (int i = 0; i < 3; ++i) {
    const std::int64_t e = t.edge[i].row_value + fixedpoint::mul_s32(static_cast<std::int32_t>(t.edge[i].slope >> 8), x_s - 128);
    if (e > 0) h += fixedpoint::mul_u32(fixedpoint::low_word_shifted_right(static_cast<std::uint64_t>(e), p.e_shift), t.omega[i]);
  }
  if (h == 0) return lod_q16_zero;
  // d/dy's numerator has the opposite sign (x_m - x): lengths do not see it.
  const auto x = static_cast<std::uint32_t>(x_s);  // a point of the view: x_s >= 0
  const std::int64_t yu = fixedpoint::mul_s64_u32(p.b[0], x) + p.ay[0], yv = fixedpoint::mul_s64_u32(p.b[1], x) + p.ay[1];
  const bool flat_y = yu == 0 && yv == 0;
  const std::int32_t along_x = p.along_x_q16;
  if (along_x == INT32_MIN && flat_y) return lod_q16_zero;
  const std::int32_t along_y = flat_y ? INT32_MIN : log2_length2_q16(yu, yv);
  const std::int32_t twice_q16 = (along_x > along_y ? along_x : along_y) + p.constant_q16 - 4 * log2_q16(h);
  // Kept within +-2^24 (+-256 levels, far beyond any chain): a piece's sums fit 32 bits.
  const std::int32_t lambda = twice_q16 >> 1;
  return std::clamp(lambda, lod_q16_zero, -lod_q16_zero);
}

// At the centre of a column.
constexpr std::int32_t lod_q16_at(const LodPlanes& p, const TriangleSetup& t, std::int32_t column) {
  return lod_q16_at_x(p, t, column * 256 + 128);
}

// lambda along a row from `begin`, linear up to (not including) `end`: value at
// begin and step per pixel, Q.16; `end_value` is lambda at `end` when end is in the span.
inline constexpr std::int32_t lod_chord_tolerance = 1 << (16 - 6);  // 1/64
inline constexpr std::int32_t lod_piece_pixels = 128;              // the step's rounding adds < 2^-10
struct LodPiece {
  std::int32_t begin, end;
  std::int32_t value, step, end_value;
};

// The piece from `column` (lambda there: `value`) within a span whose last pixel is
// `last`: n = min(2^7, last - column) pixels, its end (the next piece's start) inside
// the span, halved while lambda at its middle or quarters (in subpixels: exact points)
// strays from the chord. The step is the chord's slope rounded, by one division.
constexpr LodPiece plan_lod_piece(const LodPlanes& p, const TriangleSetup& t, std::int32_t column, std::int32_t value,
                                  std::int32_t last) {
  if (column >= last) return {column, column + 1, value, 0, value};
  std::int32_t n = last - column < lod_piece_pixels ? last - column : lod_piece_pixels;
  std::int32_t end_value = lod_q16_at(p, t, column + n);
  auto near = [](std::int32_t lambda, std::int32_t chord) {
    return lambda - chord <= lod_chord_tolerance && chord - lambda <= lod_chord_tolerance;
  };
  const std::int32_t x0 = column * 256 + 128;  // the piece's first pixel centre, subpixels
  while (n > 2) {
    // The middle and the quarters: lambda's curvature changes sign where the larger
    // derivative changes (a corner) and within the d/dy term (an inflection).
    // Both ends within [-2^24, 2^24]: their sums and differences fit 32 bits.
    const std::int32_t middle = lod_q16_at_x(p, t, x0 + n * 128);
    const std::int32_t quarter = (end_value - value) >> 2;
    const bool linear = near(middle, value + ((end_value - value) >> 1)) &&
                        near(lod_q16_at_x(p, t, x0 + n * 64), value + quarter) &&
                        near(lod_q16_at_x(p, t, x0 + n * 192), end_value - quarter);
    if (linear) break;
    // Halved: its end is the middle when that is a pixel centre.
    end_value = (n & 1) == 0 ? middle : lod_q16_at(p, t, column + (n >> 1));
    n >>= 1;
  }
  if (n == 2) {  // two pixels, both exact when the piece ends at its second
    end_value = lod_q16_at(p, t, column + 1);
    n = 1;
  }
  // The step rounded (floor((d + n/2) / n)): after up to 2^7 pixels the sum strays by
  // at most 2^6 * 2^-16 = 2^-10. |d| <= 2^25: the sum fits 32 bits.
  const std::int32_t step =
      n == 1 ? end_value - value : fixedpoint::FloorDivisor(static_cast<std::uint32_t>(n)).floor_div(end_value - value + (n >> 1)).quotient;
  return {column, column + n, value, step, end_value};
}

// A run's level and mix. With d = lambda rounded to Q.8: below 0 the run reads
// level 0 alone, at or above last_level the last level alone; else level
// k = floor(d / 256) and k + 1, the weight of k + 1 at pixel i being
// f_i = (base + i step) >> 8 in [0, 256).
struct RunLevel {
  std::int32_t level;  // k
  std::int32_t base;   // lambda at the run's first pixel + 2^7 - k 2^16 (Q.16); 0 when one level
  std::int32_t step;   // per pixel (Q.16); 0 when one level
  bool one_level;
};

// -1 below level 0, last_level at or above it, else floor(d / 256).
constexpr std::int32_t level_band(std::int32_t lambda_q16, std::int32_t last_level) {
  const std::int32_t d = (lambda_q16 + 128) >> 8;
  return d < 0 ? -1 : (d >= (last_level << 8) ? last_level : d >> 8);
}

// Cuts `count` (halving) until the run's first and last pixels, and so all
// between (lambda is linear along it), are in the same band.
constexpr RunLevel run_level(std::int32_t value, std::int32_t step, std::int32_t last_level, std::int32_t& count) {
  const std::int32_t band = level_band(value, last_level);
  while (count > 1 && level_band(value + (count - 1) * step, last_level) != band) count = (count + 1) >> 1;
  if (band < 0) return {0, 0, 0, true};
  if (band == last_level) return {last_level, 0, 0, true};
  return {band, value + 128 - (band << 16), step, false};
}

// MipRule::segment: one level for the pixels first..last of a uv segment, read
// bilinear: lambda at the middle pixel rounded to the nearest level, clamped to
// [0, last_level]. lambda within +-2^24: adding the half does not overflow.
constexpr RunLevel segment_level(const LodPlanes& p, const TriangleSetup& t, std::int32_t first, std::int32_t last) {
  const std::int32_t k = (lod_q16_at(p, t, first + ((last - first) >> 1)) + (1 << 15)) >> 16;
  return {std::clamp(k, std::int32_t{0}, p.last_level), 0, 0, true};
}

}  // namespace spanlight
