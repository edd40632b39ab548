// Stage 2c, small triangles: the triangles a model is made of. When all three
// vertices are inside the clip planes, the bounding box is under 64 pixels a
// side and the triangle is flat enough in 1/w that affine interpolation of its
// uv stays within the knobs' tolerance, setup is done in 32 bits:
//
// * edges relative to the box's corner: |dx|, |dy| < 2^14 subpixels and the
//   corner within 2^14 + 256 of every vertex, so an edge function is below 2^30
//   and steps by 256 dx < 2^22 a row: exact, with the same top-left rule and
//   the same pixels as setup.hpp's int64 edges;
// * each edge's bound on a row stepped from the one above: by the row step's
//   quotient and remainder (one division, where the core has a divide
//   instruction), or by search, a few compares and no division at all
//   (Cortex-M0+): no 64-bit division, no library call;
// * depth affine across the triangle and uv a quadratic within tolerance (see
//   QuadraticAttribute), from one product each with the reciprocal of the
//   area, stepped per row and per pixel with no divide at all;
// * slivers (a barycentric beyond [-12, 12] somewhere in the box) take the
//   general path: here every attribute relative to vertex 0 fits 32 bits.
#pragma once

#include <climits>
#include <cstdint>
#include <utility>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/divide.hpp"
#include "fixedpoint/reciprocal.hpp"
#include "spanlight/1_vertex/project.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

inline constexpr std::int32_t small_triangle_extent = 1 << 14;  // subpixels: 64 pixels

// Where a sloped edge bounds a row, stepped down the rows: floor((E_row - bias) / |slope|)
// as quotient and remainder (the row's last column inside a right edge, minus the first
// inside a left one). Two ways to step it, the same quotients, each the cheaper where it is
// used (measured on mesh_bear): with a divide instruction (Cortex-M3/M4/M7, the host) the row
// step's own quotient and remainder, one carry a row; without one (Cortex-M0+) no division at
// all, the remainder gains row_step and the quotient follows by whole divisors (`settle`).
template <bool Search>
struct EdgeBoundBy {
  std::int32_t quotient, remainder;            // remainder in [0, divisor) between rows
  std::int32_t quotient_step, remainder_step;  // Search: 0 and row_step
  std::int32_t divisor;                        // |slope|

  [[gnu::always_inline]] constexpr void next_row() {
    remainder += remainder_step;
    if constexpr (Search) {
      settle();
    } else {
      quotient += quotient_step;
      if (remainder >= divisor) {
        remainder -= divisor;
        ++quotient;
      }
    }
  }
  // The remainder back into [0, divisor). From a row's start it moves |dx / dy| + 1 divisors at most
  // (|row_step| = |dx| 256, divisor = |dy| 256), and an edge's quotient stays within the box on the
  // rows it spans: at most 65 steps over all of them.
  [[gnu::always_inline]] constexpr void settle() {
    std::int32_t q = quotient, r = remainder;  // in registers: the fields would be stored at every step
    while (r < 0) {
      r += divisor;
      --q;
    }
    while (r >= divisor) {
      r -= divisor;
      ++q;
    }
    quotient = q;
    remainder = r;
  }
};
using EdgeBound = EdgeBoundBy<!fixedpoint::has_divide_instruction>;

// One edge over the rows of a small triangle: E(c) = slope c + row_value >= bias.
struct SmallEdge {
  std::int32_t slope, row_value, row_step, bias;
  std::int32_t top;  // the upper end's y, relative to the corner

  constexpr void start(std::int32_t ax, std::int32_t ay, std::int32_t bx, std::int32_t by) {
    const std::int32_t dx = bx - ax, dy = by - ay;
    top = ay < by ? ay : by;
    bias = (dy < 0 || (dy == 0 && dx > 0)) ? 0 : 1;  // top-left rule, as Edge::start
    slope = -256 * dy;
    row_step = 256 * dx;
    row_value = dy * ax - dx * ay;  // E at the corner (column 0, row 0 of the box): |.| < 2^29
  }
  // Where it bounds row `down` of the box (0 <= down < 65: |E| there < 2^29 + 2^28.1), a row it
  // spans, stepped from there.
  template <bool Search = !fixedpoint::has_divide_instruction>
  constexpr EdgeBoundBy<Search> bound(std::int32_t down) const {
    const std::int32_t divisor = slope > 0 ? slope : -slope;
    const std::int32_t e = row_value + down * row_step - bias;
    if constexpr (Search) {
      // From column 0: on a row the edge spans it crosses the row inside the box, so a left
      // edge's quotient (minus its first column inside) and a right edge's (its last) lie in
      // [-65, 65], that many steps away at most.
      EdgeBoundBy<true> b{0, e, 0, row_step, divisor};
      b.settle();
      return b;
    } else {
      const fixedpoint::FloorDivisor d(static_cast<std::uint32_t>(divisor));
      const auto q = d.floor_div(e), s = d.floor_div(row_step);
      return {q.quotient, q.remainder, s.quotient, s.remainder, divisor};
    }
  }
};

// An attribute affine over the box: value at the corner and per column and row,
// in its stepping scale (wrapping modulo 2^32).
struct AffineAttribute {
  std::uint32_t at_corner, per_column, per_row;
};

// A barycentric over the box, scaled by 2^26: |value| <= 12 and |steps| <= 24
// there (setup_small refuses slivers), so each fits 32 bits, and a product with
// an attribute's difference (|d| < 2^31) fits 64.
inline constexpr int barycentric_bits = 26;
struct BarycentricPlane {
  std::int32_t at_corner, per_column, per_row;
};

struct SmallTriangle {
  std::int32_t column0, row0;        // the box's corner (pixel column and row)
  std::int32_t row_begin, row_end;   // rows to walk, absolute
  EdgeBound left, right;             // the sloped edges bounding the current row from the left, from the right
  EdgeBound lower;                   // on the side with two edges, the one below the middle vertex:
  std::int32_t rows_to_turn;         // it takes over after this many more rows (<= 0: no turn ahead)
  bool lower_is_left;
  BarycentricPlane l1, l2;           // of the vertices in setup slots 1 and 2
  std::uint8_t order[3];

  // a0 + da1 l1 + da2 l2 in units of the attribute's exact scale times 2^shift
  // (shift <= 26). The planes' rounding (2^-27 each step) moves a value within
  // the box by at most (|da1| + |da2|) 130 * 2^-27.
  constexpr AffineAttribute affine(std::int32_t a0, std::int32_t da1, std::int32_t da2, int shift) const {
    const int down = barycentric_bits - shift;
    // The low word of the sum >> down (down <= 26): what the cast keeps. mul_s32_setup and the
    // word shift keep __muldi3 and __aeabi_lasr out of M0+ setup.
    auto mix = [&](std::int32_t p1, std::int32_t p2) {
      const std::int64_t sum = fixedpoint::mul_s32_setup(da1, p1) + fixedpoint::mul_s32_setup(da2, p2);
      return fixedpoint::low_word_shifted_right(static_cast<std::uint64_t>(sum), down);
    };
    return {(static_cast<std::uint32_t>(a0) << shift) + mix(l1.at_corner, l2.at_corner), mix(l1.per_column, l2.per_column),
            mix(l1.per_row, l2.per_row)};
  }

  // The columns of the row the edges stand at, relative to the corner: [lo, hi], empty if lo > hi.
  // (A horizontal edge has trimmed row_begin and row_end instead.)
  constexpr bool columns(std::int32_t& lo, std::int32_t& hi) const {
    lo = -left.quotient > lo ? -left.quotient : lo;
    hi = right.quotient < hi ? right.quotient : hi;
    return lo <= hi;
  }
  // Out of line: its two bounds step in registers of their own (inlined into the row loop, they
  // spill there on Cortex-M0+).
  [[gnu::noinline]] constexpr void next_row() {
    left.next_row();
    right.next_row();
    if (--rows_to_turn == 0) (lower_is_left ? left : right) = lower;
  }
};

// Whether a pass may still take a pixel of the box: columns [column0, column0 + columns) of rows
// [row_begin, row_end), absolute. By default it may.
struct AnyPixelMaySee {
  constexpr bool operator()(std::int32_t, std::int32_t, std::int32_t, std::int32_t) const { return true; }
};

// Builds the setup of a small triangle from its snapped window vertices; false
// when it is not small (the caller takes the general path), and `covers` false
// when it is culled, has no area or no row, or `may_see` says no pixel of its box
// can pass (then it draws nothing either way).
template <typename MaySee = AnyPixelMaySee>
constexpr bool setup_small(const ScreenVertex (&in)[3], Cull cull, int height, SmallTriangle& t, bool& covers,
                           const MaySee& may_see = {}) {
  covers = false;
  const std::int32_t x_min = fixedpoint::least_of(in[0].x, in[1].x, in[2].x), x_max = fixedpoint::greatest_of(in[0].x, in[1].x, in[2].x);
  const std::int32_t y_min = fixedpoint::least_of(in[0].y, in[1].y, in[2].y), y_max = fixedpoint::greatest_of(in[0].y, in[1].y, in[2].y);
  if (x_max - x_min >= small_triangle_extent || y_max - y_min >= small_triangle_extent) return false;
  // The corner: the pixel centre at or left of / above the box (|x| < 2^21: >> is floor).
  t.column0 = (x_min - 128) >> 8;
  t.row0 = (y_min - 128) >> 8;
  const std::int32_t ox = t.column0 * 256 + 128, oy = t.row0 * 256 + 128;
  const std::int32_t x0 = in[0].x - ox, y0 = in[0].y - oy;  // each in [0, 2^14 + 256)
  std::int32_t x1 = in[1].x - ox, y1 = in[1].y - oy, x2 = in[2].x - ox, y2 = in[2].y - oy;
  std::int32_t area2 = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0);  // < 2^29
  if (area2 == 0) return true;
  if (cull == Cull::back && area2 > 0) return true;  // clockwise on screen
  t.order[0] = 0;
  t.order[1] = area2 > 0 ? 1 : 2;
  t.order[2] = area2 > 0 ? 2 : 1;
  if (area2 < 0) {  // setup order: vertices 0, 2, 1
    area2 = -area2;
    std::swap(x1, x2);
    std::swap(y1, y2);
  }
  const CentredRows centred = rows_centred_in(y_min, y_max);  // as setup_triangle takes them
  std::int32_t r0 = centred.first, r1 = centred.end;
  if (r0 < 0) r0 = 0;
  if (r1 > height) r1 = height;
  if (r0 >= r1) return true;
  // Edge i runs from slot i + 1 to slot i + 2, as in setup_triangle.
  SmallEdge edge[3];
  edge[0].start(x1, y1, x2, y2);
  edge[1].start(x2, y2, x0, y0);
  edge[2].start(x0, y0, x1, y1);
  // Slivers go the general way: over the box every barycentric must stay within
  // [-12, 12] (|E_i| <= 12 D at its four corners: E is affine), so that the
  // planes and the attributes relative to vertex 0 fit 32 bits. In 32 bits:
  // |E| < 2^30 at the corner, |slope| columns and |row_step| rows < 2^28.1 each.
  const std::int32_t columns = ((x_max - ox) >> 8) + 1, rows = ((y_max - oy) >> 8) + 1;
  const std::int32_t limit = area2 < (INT32_MAX / 12) ? 12 * area2 : INT32_MAX;
  int level = 3;
  for (int i = 0; i < 3; ++i) {
    const SmallEdge& e = edge[i];
    const std::int32_t across = e.slope * columns, down = e.row_step * rows;
    // The four corners' least and greatest values (|.| < 2^30 + 2 * 2^28.1 < 2^31).
    const std::int32_t lowest = e.row_value + (across < 0 ? across : 0) + (down < 0 ? down : 0);
    const std::int32_t highest = e.row_value + (across > 0 ? across : 0) + (down > 0 ? down : 0);
    if (highest > limit || lowest < -limit) return false;
    if (e.slope == 0) level = i;
  }
  // A horizontal edge's E is the same all along a row, so it takes or leaves whole rows:
  // those at the end where it lies. E at row R: row_value + (R - row0) row_step, |.| < 2^29 + 2^28.1.
  if (level < 3) {
    const SmallEdge& e = edge[level];
    auto inside = [&](std::int32_t row) { return e.row_value + (row - t.row0) * e.row_step >= e.bias; };
    while (r0 < r1 && !inside(r0)) ++r0;
    while (r1 > r0 && !inside(r1 - 1)) --r1;
    if (r0 >= r1) return true;
  }
  // Behind what the pass has drawn all over the box: the rest of setup (planes, edge bounds) is not needed.
  if (!may_see(t.column0, columns, r0, r1)) return true;
  // The barycentrics' planes: E_i / D, times 2^26. rcp ~ 2^(30 + L) / D (L the bit length of D),
  // so x / D 2^26 = x rcp / 2^(4 + L); |x| < 2^30 and rcp <= 2^31: the product fits 64 bits.
  const int area_log2 = fixedpoint::bit_length32(static_cast<std::uint32_t>(area2));
  const std::uint32_t rcp = fixedpoint::reciprocal_normalised<8, 2>(static_cast<std::uint32_t>(area2) << (32 - area_log2));
  const int shift = 4 + area_log2;  // <= 33
  const auto half = static_cast<std::int64_t>(fixedpoint::power_of_two64(shift - 1));
  auto plane = [&](const SmallEdge& e) {
    // Rounded: within 2^-27 of x rcp / 2^shift (|x rcp| < 2^61: no overflow). rcp < 2^31 fits int32.
    auto scaled = [&](std::int32_t x) {
      return fixedpoint::floor_shifted_right(fixedpoint::mul_s32_setup(x, static_cast<std::int32_t>(rcp)) + half, shift);
    };
    return BarycentricPlane{scaled(e.row_value), scaled(e.slope), scaled(e.row_step)};
  };
  t.l1 = plane(edge[1]);
  t.l2 = plane(edge[2]);
  t.row_begin = r0;
  t.row_end = r1;
  // The sloped edges, from the first row on: one each side, or (no horizontal edge: the three dy
  // sum to 0) two on one side that meet at the middle vertex. A row whose centre lies above that
  // vertex is inside the lower edge's half-plane wherever it is inside the other two (the lower
  // edge does not reach its height), and one below is inside the upper one's: each row needs only
  // the edge of its half. On the vertex's own row both give the same column (same direction,
  // same bias), so the lower one takes over from the row whose centre is at or below it.
  // [0] left (slope > 0), [1] right. Each side gets one edge at least (the three dy sum to 0 and
  // are not all 0), and side[s][1] is read only when count[s] == 2: no zeroing (a memset call).
  const SmallEdge* side[2][2];
  int count[2] = {0, 0};
  for (const SmallEdge& e : edge) {
    if (e.slope != 0) {
      const int s = e.slope > 0 ? 0 : 1;
      side[s][count[s]++] = &e;
    }
  }
  const int down = r0 - t.row0;
  t.rows_to_turn = 0;
  for (int s = 0; s < 2; ++s) {
    const SmallEdge* first = side[s][0];
    if (count[s] == 2) {
      const bool zero_is_upper = side[s][0]->top < side[s][1]->top;
      const SmallEdge& upper = *side[s][zero_is_upper ? 0 : 1];
      const SmallEdge& lower = *side[s][zero_is_upper ? 1 : 0];
      const std::int32_t turn = t.row0 + ((lower.top + 255) >> 8);  // the first row centred at or below the middle vertex
      first = turn <= r0 ? &lower : &upper;
      if (turn > r0 && turn < r1) {
        t.lower = lower.bound(turn - t.row0);
        t.rows_to_turn = turn - r0;
        t.lower_is_left = s == 0;
      }
    }
    (s == 0 ? t.left : t.right) = first->bound(down);
  }
  covers = true;
  return true;
}

// Perspective-correct uv over a small triangle as a quadratic. With the
// vertices' perspective weights w_i = w' (1 + e_i) about their mean w', the
// exact value is u = u_0 + C / (1 + e), where C = sum l_i (u_i - u_0)(1 + e_i)
// and e = sum l_i e_i are affine on screen. The quadratic q = u_0 + C (1 - e)
// differs from it by
//   u - q = C e^2 / (1 + e),  |u - q| <= D (1 + eps) eps^2 / (1 - eps) < 1.07 D eps^2
// inside the triangle (|C| <= (1 + eps) D there), D the uv range and
// eps = max |e_i| <= 1/32. Along a row it steps with two adds a pixel:
// q(c + 1) - q(c) = step, step += curve.
struct PerspectiveWeights {
  std::int32_t e[3];  // e_i, Q0.30 (|e_i| <= 2^25)
  std::int32_t largest;
};

// The e_i of three vertices (input order), or false when one is beyond 1/32.
constexpr bool perspective_weights_of(const ScreenVertex (&v)[3], PerspectiveWeights& out) {
  int e_min = v[0].inv_w_exponent;
  for (const ScreenVertex& s : v) e_min = s.inv_w_exponent < e_min ? s.inv_w_exponent : e_min;
  std::uint32_t w[3];
  for (int i = 0; i < 3; ++i) {
    const int shift = v[i].inv_w_exponent - e_min + 2;  // below 2^30 each: their sum fits 32 bits
    w[i] = shift >= 32 ? 0u : v[i].inv_w_mantissa >> shift;
  }
  const std::uint32_t sum = w[0] + w[1] + w[2];
  if (sum == 0) return false;
  const fixedpoint::Reciprocal rcp = fixedpoint::reciprocal<8, 2>(sum);  // relative error < 2^-28.9: it only moves the e_i together
  out.largest = 0;
  for (int i = 0; i < 3; ++i) {
    // 3 w_i / sum - 1 in Q0.30: 3 w_i < 2^32, times the mantissa (< 2^31) over 2^(shift - 30).
    // The ratio is at most 3 * 2^30 (3 w_i / sum <= 3, y <= 1 / sum): one word.
    const std::uint32_t ratio = fixedpoint::word_shifted_right(fixedpoint::mul_u32(3u * w[i], rcp.mantissa), rcp.shift - 30);
    // |e_i| <= 1/32 (|sum l_i e_i| < 2^30.2 with |l_i| <= 12): ratio within 2^25 of 2^30, one
    // unsigned compare of the word (below the range it wraps above it).
    if (ratio - ((1u << 30) - (1u << 25)) > (1u << 26)) return false;
    out.e[i] = static_cast<std::int32_t>(ratio - (1u << 30));  // in [-2^25, 2^25]
    const std::int32_t m = out.e[i] < 0 ? -out.e[i] : out.e[i];
    out.largest = m > out.largest ? m : out.largest;
  }
  return true;
}

// Whether the quadratic is within 2^-T texel of the perspective value at every pixel the
// triangle covers, D = uv_range in texels * 2^frac and 2^texel_bits step units a texel:
//   its own error (above)                            < 1.07 D eps^2,
//   the planes' rounding (SmallTriangle::affine)     moves C by (|d1| + |d2|)(1 + eps) 130 * 2^-27
//                                                    < D 2^-18.9, and C e by |C| 130 * 2^-29 < D 2^-21.9,
//   the floors of d (1 + e_k) 2^extra                < 2^-extra <= max(D 2^-24, one step unit),
//   the coefficients' floors (QuadraticAttribute)    < 3 * 65^2 + 2 * 65 + 1 < 2^14 - 1 step units,
// so 1.125 D eps^2 + D 2^-18 <= 2^-T - 2^(14 - texel_bits) texel is enough.
constexpr bool quadratic_enough(const PerspectiveWeights& w, std::int32_t uv_range, int frac, int texel_bits,
                                int tolerance_log2) {
  if (tolerance_log2 == 0) return true;
  const auto largest = static_cast<std::uint32_t>(w.largest);
  const auto eps2 = static_cast<std::uint32_t>(fixedpoint::mul_u32(largest, largest) >> 30);  // Q0.30, <= 2^20
  // In exact units * 2^30: D (1.125 eps^2 + 2^-18) < 2^26 * 2^21.
  const std::uint64_t error = fixedpoint::mul_u32(static_cast<std::uint32_t>(uv_range), eps2 + (eps2 >> 3) + (1u << 12));
  const int budget_log2 = 30 + frac - tolerance_log2, rounding_log2 = 30 + frac + 14 - texel_bits;
  if (rounding_log2 >= budget_log2) return false;
  if (budget_log2 >= 63) return true;
  return error <= fixedpoint::power_of_two64(budget_log2) - fixedpoint::power_of_two64(rounding_log2);
}

// One coordinate (u or v) over a small triangle as a polynomial in the column
// c and row r from the corner, in the step scale (wrapping modulo 2^32, as a
// repeating texture's coordinate does):
//   q = q00 + q10 c + q01 r + q20 c^2 + q11 c r + q02 r^2,
// from q = u_0 + C (1 - e) with C and e affine (each product of C's terms and
// e's is /2^29). The coefficients are floored in the step scale (one unit each),
// so at column c and row r <= 65 of the box they add less than
// 1 + c + r + c^2 + c r + r^2 < 2^14 units (quadratic_enough counts them).
struct QuadraticAttribute {
  std::uint32_t q00, q10, q01, q20, q11, q02;

  // From the affine C (exact units * 2^extra) and e (Q0.29), u_0 in the step scale, to_step = shift - extra.
  static constexpr QuadraticAttribute of(std::uint32_t base, const AffineAttribute& c, const AffineAttribute& e, int to_step) {
    const auto C0 = static_cast<std::int32_t>(c.at_corner), Cc = static_cast<std::int32_t>(c.per_column),
               Cr = static_cast<std::int32_t>(c.per_row);
    const auto e0 = static_cast<std::int32_t>(e.at_corner), ec = static_cast<std::int32_t>(e.per_column),
               er = static_cast<std::int32_t>(e.per_row);
    const int down = 29 - to_step;  // e in Q0.29; to_step <= 24
    auto up = [&](std::uint32_t x) { return x << to_step; };
    // (x e) in the step scale: the low word of the product >> down, 5 <= down <= 29.
    auto product = [&](std::int64_t p) { return fixedpoint::low_word_shifted_right(static_cast<std::uint64_t>(p), down); };
    constexpr auto mul = fixedpoint::mul_s32_setup;  // exact 32 x 32 products; no __muldi3 on M0+
    // Six products, not nine: a cross term x y' + x' y is (x + x')(y + y') - x y - x' y'.
    // Every sum fits 32 bits. The sliver test bounds each barycentric's |column step| columns +
    // |row step| rows by 24 (columns, rows >= 1), so with |d (1 + e_k)| 2^extra < 2^25.05 and
    // |e_i| <= 2^24 (Q0.29): |Cc| + |Cr| <= 48 * 2^25.05 < 2^30.6 and |ec| + |er| <= 3 * 2^24 * 24
    // < 2^30.2; C0 + Cc and C0 + Cr are C at a point of the box (|C| < 2^29.7), e likewise (< 2^29.2).
    const std::int64_t p00 = mul(C0, e0), pcc = mul(Cc, ec), prr = mul(Cr, er);
    QuadraticAttribute q{};
    q.q00 = base + up(c.at_corner) - product(p00);
    q.q10 = up(c.per_column) - product(mul(C0 + Cc, e0 + ec) - p00 - pcc);
    q.q01 = up(c.per_row) - product(mul(C0 + Cr, e0 + er) - p00 - prr);
    q.q20 = 0u - product(pcc);
    q.q11 = 0u - product(mul(Cc + Cr, ec + er) - pcc - prr);
    q.q02 = 0u - product(prr);
    return q;
  }

  // The value and step at column c of row r of the box, exactly (mod 2^32), evaluated afresh at
  // each run rather than stepped down the rows: a row the depth test hides costs nothing. The
  // curve, 2 q20, is the same at every pixel.
  constexpr void at(std::uint32_t r, std::uint32_t c, std::uint32_t& v, std::uint32_t& step) const {
    const std::uint32_t slope_at_c = q10 + q11 * r + q20 * c;
    v = q00 + (q01 + q02 * r) * r + slope_at_c * c;
    step = slope_at_c + q20 * (c + 1);
  }
  constexpr std::uint32_t curve() const { return 2 * q20; }
};

// A coordinate's quadratic over the small triangle t: u_0 + offset in the step scale (`base`,
// 2^shift units an exact unit), d1 and d2 the differences u_k - u_0 of the vertices in setup
// slots 1 and 2 (|d| <= D, the uv range, in exact units) with their weights' e1, e2 (Q0.30),
// and e the weights' plane over the box (SmallTriangle::affine of the e_i / 2, Q0.29, shift 0).
// C is carried in exact units * 2^extra, extra = min(shift, 25 - bit length of D): over the box
// the barycentrics stay within [-12, 12], so |C| <= 24 (1 + 1/32) D 2^extra < 2^29.7, and its
// steps fit 32 bits with the room QuadraticAttribute::of needs.
constexpr QuadraticAttribute perspective_quadratic(const SmallTriangle& t, std::uint32_t base, int shift,
                                                   std::int32_t range, std::int32_t d1, std::int32_t e1,
                                                   std::int32_t d2, std::int32_t e2, const AffineAttribute& e) {
  const int extra_room = 25 - fixedpoint::bit_length32(static_cast<std::uint32_t>(range));
  const int extra = extra_room < shift ? extra_room : shift;
  // d (1 + e_k) 2^extra: |d 2^extra| < 2^26, and the product's floor (its low word: it fits) is
  // within one unit.
  auto weighted = [&](std::int32_t d, std::int32_t e_k) {
    const auto product = static_cast<std::uint64_t>(fixedpoint::mul_s32_setup(d, e_k));
    return static_cast<std::int32_t>(static_cast<std::uint32_t>(d) * (1u << extra) +
                                     fixedpoint::low_word_shifted_right(product, 30 - extra));
  };
  return QuadraticAttribute::of(base, t.affine(0, weighted(d1, e1), weighted(d2, e2), 0), e, shift - extra);
}


}  // namespace spanlight
