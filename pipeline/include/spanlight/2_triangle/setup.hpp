// Stage 2, triangle setup: orientation and culling, exact integer edge
// functions with the top-left rule, and the normalisations the span stage
// needs (1/(2*area) for barycentrics, per-vertex perspective weights).
//
// Bounds: snapped coordinates stay within +-2^21 subpixels (the clip stage's
// guard band), so edge deltas are < 2^22, an edge function is < 2^45 in int64,
// and 256 * delta < 2^30 fits the int32 steppers.
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/divide.hpp"
#include "spanlight/1_vertex/project.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

// One edge a->b as a half-plane over pixel columns of a row:
//   E(c) = slope * c + row_value >= bias,   E = dx*(py - ay) - dy*(px - ax),
// with px = 256c + 128. A left edge (slope > 0) bounds columns from below, a
// right edge from above; a horizontal edge admits a whole row or none of it.
// Top-left rule: bias 0 on top and left edges, 1 on the others, so a centre
// exactly on a shared edge belongs to one triangle only.
// Only E and the bound need 64 bits (|E| < 2^45); everything else is a word,
// which keeps the per-row steps single adds on Cortex-M0+ and the setup's
// three edges 48 bytes each on the stack.
struct Edge {
  std::int64_t row_value;  // E at column 0 of the current row, |.| < 2^45
  // floor((row_value - bias) / |slope|) kept incrementally: quotient + remainder.
  std::int64_t quotient;
  std::int32_t slope;      // dE per column, -256*dy: |.| < 2^30
  std::int32_t row_step;   // 256*dx: |.| < 2^30
  std::int32_t bias;
  std::int32_t divisor;    // |slope|; 0 for a horizontal edge (no bound)
  std::int32_t remainder;  // in [0, divisor): a remainder plus a step stays below 2^31
  std::int32_t quotient_step;   // floor(row_step / divisor): |.| <= 2^30 / 256 (divisor >= 256)
  std::int32_t remainder_step;  // in [0, divisor)

  constexpr void start(std::int32_t ax, std::int32_t ay, std::int32_t bx, std::int32_t by, std::int32_t row0_centre_y) {
    const std::int32_t dx = bx - ax, dy = by - ay;  // |.| < 2^22
    const bool top_left = dy < 0 || (dy == 0 && dx > 0);
    bias = top_left ? 0 : 1;
    slope = -256 * dy;
    row_step = 256 * dx;
    divisor = slope > 0 ? slope : -slope;
    // |row0_centre_y - ay|, |128 - ax| < 2^23: each product < 2^45.
    row_value = fixedpoint::mul_s32(dx, row0_centre_y - ay) - fixedpoint::mul_s32(dy, 128 - ax);
    if (divisor != 0) {
      // Exact floors without a 64-bit divide.
      const auto d = static_cast<std::uint32_t>(divisor);
      const fixedpoint::WideFloorDivMod start = fixedpoint::floor_div_wide(row_value - bias, d);
      const fixedpoint::WideFloorDivMod step = fixedpoint::floor_div_wide(row_step, d);
      quotient = start.quotient;
      remainder = static_cast<std::int32_t>(start.remainder);
      quotient_step = static_cast<std::int32_t>(step.quotient);
      remainder_step = static_cast<std::int32_t>(step.remainder);
    } else {
      quotient = 0;
      remainder = quotient_step = remainder_step = 0;
    }
  }

  constexpr void next_row() {
    row_value += row_step;
    if (divisor != 0) {
      quotient += quotient_step;
      remainder += remainder_step;
      if (remainder >= divisor) {
        remainder -= divisor;
        ++quotient;
      }
    }
  }

  // The state next_row() would reach after n rows (0 <= n < 2^13), in one step:
  // the remainders add to below (n + 1) |slope| < 2^43, so one floor division
  // carries them into the quotient. A band skips the rows above it this way.
  constexpr void skip_rows(std::int32_t n) {
    row_value += fixedpoint::mul_s32(row_step, n);
    if (divisor != 0) {
      const fixedpoint::WideFloorDivMod carry = fixedpoint::floor_div_wide(
          remainder + fixedpoint::mul_s32(remainder_step, n), static_cast<std::uint32_t>(divisor));
      quotient += fixedpoint::mul_s32(quotient_step, n) + carry.quotient;
      remainder = static_cast<std::int32_t>(carry.remainder);
    }
  }

  // |slope| < 2^30: a 32x32 product.
  constexpr std::int64_t value_at(std::int32_t column) const { return fixedpoint::mul_s32(slope, column) + row_value; }
};

struct TriangleSetup {
  Edge edge[3];  // edge i runs from vertex i+1 to vertex i+2: E_i = 2*area * lambda_i
  std::int32_t row_begin, row_end;  // rows whose centres lie within the vertical extent
  // lambda_i in Q0.30 = ((E_i >> area_shift) * area_rcp) >> 32 (area_shift < 0: shift left), D >> area_shift in [2^31, 2^32)
  int area_shift;
  std::uint32_t area_rcp;  // ~ 2^62 / (D >> area_shift), in (2^30, 2^31]; D = 2 * area in subpixel^2
  std::int32_t z0, dz1, dz2;  // window depth at vertex 0 and the deltas to 1 and 2, Q1.30
  // Depth steps by dz/dx per pixel in Q0.32 from each span's first pixel, so
  // a pixel's depth depends only on its span, never on how a pass cuts the
  // span: every pass sees bit-identical depth. Triangles too steep for the
  // gradient to fit 32 bits (|dz/dx| >= 1/2 per pixel) evaluate depth exactly
  // at each pixel instead.
  std::int32_t dzdx;
  bool depth_per_pixel;
  std::uint32_t omega[3];     // perspective weights, proportional to 1/w_i, max in [2^30, 2^31]
  std::uint8_t order[3];      // which input vertex sits at each setup slot (orientation swap)
};

constexpr std::int64_t signed_double_area(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
  return (std::int64_t{b.x} - a.x) * (std::int64_t{c.y} - a.y) - (std::int64_t{b.y} - a.y) * (std::int64_t{c.x} - a.x);
}

// Whether the snapped corners run clockwise as seen in the image: the triangle shows the camera
// its back (signed_double_area > 0). |x|, |y| < 2^21, so each difference fits 32 bits. Differences
// in [-2^15, 2^15) (under 128 pixels a side: most of a model's triangles) give products of at
// most 2^30 whose difference stays within 2^31 - 2^15: on a core without a long multiply
// (Cortex-M0+) no 64-bit product there.
constexpr bool faces_away(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c) {
  const std::int32_t x1 = b.x - a.x, y1 = b.y - a.y, x2 = c.x - a.x, y2 = c.y - a.y;
  auto in_15_bits = [](std::int32_t d) { return static_cast<std::uint32_t>(d) + (1u << 15) < (1u << 16); };
  if (!fixedpoint::has_long_multiply && in_15_bits(x1) && in_15_bits(y1) && in_15_bits(x2) && in_15_bits(y2))
    return x1 * y2 - y1 * x2 > 0;
  return fixedpoint::mul_s32_setup(x1, y2) - fixedpoint::mul_s32_setup(y1, x2) > 0;
}

// Builds the setup; false when the triangle is culled, has no area, or
// covers no row of the target. In y-down window coordinates a triangle that
// is counter-clockwise as seen in the image (front) has a negative area.
constexpr bool setup_triangle(const ScreenVertex (&in)[3], Cull cull, int height, TriangleSetup& t) {
  std::int64_t area2 = signed_double_area(in[0], in[1], in[2]);
  if (area2 == 0) return false;
  if (cull == Cull::back && area2 > 0) return false;  // clockwise on screen
  t.order[0] = 0;
  t.order[1] = area2 > 0 ? 1 : 2;
  t.order[2] = area2 > 0 ? 2 : 1;
  if (area2 < 0) area2 = -area2;
  const ScreenVertex& v0 = in[t.order[0]];
  const ScreenVertex& v1 = in[t.order[1]];
  const ScreenVertex& v2 = in[t.order[2]];

  const std::int32_t y_min = fixedpoint::least_of(v0.y, v1.y, v2.y), y_max = fixedpoint::greatest_of(v0.y, v1.y, v2.y);
  const CentredRows centred = rows_centred_in(y_min, y_max);
  std::int32_t r0 = centred.first, r1 = centred.end;
  if (r0 < 0) r0 = 0;
  if (r1 > height) r1 = height;
  if (r0 >= r1) return false;
  t.row_begin = r0;
  t.row_end = r1;

  const std::int32_t centre_y = r0 * 256 + 128;
  const ScreenVertex* v[3] = {&v0, &v1, &v2};
  for (int i = 0; i < 3; ++i) {
    const ScreenVertex& a = *v[i == 2 ? 0 : i + 1];  // (i + 1) mod 3 and (i + 2) mod 3, no divide on M0+
    const ScreenVertex& b = *v[i == 0 ? 2 : i - 1];
    t.edge[i].start(a.x, a.y, b.x, b.y, centre_y);
  }

  // Normalise D into [2^31, 2^32) so lambda = E/D is one 32x32 product with
  // the table reciprocal (the vertex divide's: 8-bit table, two Newton steps,
  // relative error below 2^-28.9, docs/reciprocal.md): no division per triangle.
  t.area_shift = fixedpoint::bit_length(static_cast<std::uint64_t>(area2)) - 32;
  const auto d_norm = static_cast<std::uint32_t>(t.area_shift >= 0 ? static_cast<std::uint64_t>(area2) >> t.area_shift
                                                                    : static_cast<std::uint64_t>(area2) << -t.area_shift);
  t.area_rcp = fixedpoint::reciprocal_normalised<8, 2>(d_norm);  // ~ 2^62 / d_norm, in (2^30, 2^31]

  t.z0 = v0.z;
  t.dz1 = v1.z - v0.z;
  t.dz2 = v2.z - v0.z;
  // dz/dx in Q0.32 = 4 (dz1 slope1 + dz2 slope2) / D, dz in Q1.30 (|dz| <= 2^30), slope = dE/dcolumn
  // (|slope| < 2^30): |num| < 2^61. 4/D = rcp 2^-(60 + area_shift), rcp halved to fit int32.
  {
    const std::int64_t num = std::int64_t{t.dz1} * t.edge[1].slope + std::int64_t{t.dz2} * t.edge[2].slope;
    const int shift = 60 + t.area_shift - 1;
    const std::uint64_t magnitude = static_cast<std::uint64_t>(num < 0 ? -num : num);
    // |result| < 2^(bits(num) + 30 - shift): keep it below 2^31 (|dz/dx| < 1/2 per pixel), else per pixel.
    t.depth_per_pixel = shift < 0 || fixedpoint::bit_length(magnitude) + 30 - shift > 31;
    t.dzdx = 0;
    if (!t.depth_per_pixel) {
      const int pre = shift > 32 ? shift - 32 : 0;  // num >> pre loses at most 2^-32 of a pixel's step
      t.dzdx = static_cast<std::int32_t>(
          fixedpoint::mul_shift_wide(num >> pre, static_cast<std::int32_t>(t.area_rcp >> 1), shift - pre));
    }
  }

  // 1/w_i = mantissa_i * 2^-exponent_i; bring all three to the smallest
  // exponent (the nearest vertex). A vertex 2^31 times farther gets weight 0.
  int e_min = v0.inv_w_exponent;
  if (v1.inv_w_exponent < e_min) e_min = v1.inv_w_exponent;
  if (v2.inv_w_exponent < e_min) e_min = v2.inv_w_exponent;
  for (int i = 0; i < 3; ++i) {
    const int s = v[i]->inv_w_exponent - e_min;
    t.omega[i] = s >= 32 ? 0u : v[i]->inv_w_mantissa >> s;
  }
  return true;
}

// lambda_i at a point from its exact edge value E (0 <= E <= D inside), Q0.30, clamped to [0, 1]:
// E >> area_shift < 2^32 and area_rcp <= 2^31, so one 32x32 product.
constexpr std::int32_t barycentric(const TriangleSetup& t, std::int64_t e) {
  if (e <= 0) return 0;
  // e_norm = e >> area_shift (area_shift in [-31, 14]: D < 2^46) in one word, from 32-bit shifts;
  // beyond a word it is outside, beyond the far edge: clamp.
  const auto hi = static_cast<std::uint32_t>(static_cast<std::uint64_t>(e) >> 32), lo = static_cast<std::uint32_t>(e);
  std::uint32_t e_norm;
  if (t.area_shift >= 0) {
    if ((hi >> t.area_shift) != 0) return 1 << 30;
    e_norm = fixedpoint::low_word_shifted_right(static_cast<std::uint64_t>(e), t.area_shift);
  } else {
    const int left = -t.area_shift;  // 1 .. 31
    if (hi != 0 || (lo >> (32 - left)) != 0) return 1 << 30;
    e_norm = lo << left;
  }
  const auto lambda = static_cast<std::uint32_t>(fixedpoint::mul_u32(e_norm, t.area_rcp) >> 32);
  return lambda > (1u << 30) ? (1 << 30) : static_cast<std::int32_t>(lambda);
}

}  // namespace spanlight
