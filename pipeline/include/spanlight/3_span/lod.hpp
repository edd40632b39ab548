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
// affine in the column: per run, a few products and three logarithms.
//
// A run holds one lambda: the mean of its ends', the run cut in halves until
// they differ by at most 1/16 (hold_lod). Where lambda is monotonic along the
// run, a pixel's own is then within 1/32 + 2^-8.5 of the held one; tests/mipmap
// checks that bound on random triangles.
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "spanlight/1_vertex/project.hpp"
#include "spanlight/2_triangle/attributes.hpp"
#include "spanlight/2_triangle/setup.hpp"

namespace spanlight {

inline constexpr int lod_frac_bits = 8;                       // lambda in Q.8
inline constexpr std::int32_t lod_level_zero = INT32_MIN / 2;  // rho = 0: magnified without end

// log2(1 + i/32) in Q.16, i = 0..32.
inline constexpr std::uint32_t log2_q16_table[33] = {
    0,     2909,  5732,  8473,  11136, 13727, 16248, 18704, 21098, 23433, 25711, 27936, 30109, 32234, 34312, 36346, 38336,
    40286, 42196, 44068, 45904, 47705, 49472, 51207, 52911, 54584, 56229, 57845, 59434, 60997, 62534, 64047, 65536};

// log2 x in Q.16 for x > 0: the leading bit, then the table, linear between
// its 1/32 steps. Linear interpolation of log2 over a step of 1/32 is within
// (1/32)^2 / (8 ln 2) = 2^-12.5 of it, the position's truncation adds 2^-16:
// |error| < 2^-12.3.
constexpr std::int32_t log2_q16(std::uint64_t x) {
  const int e = fixedpoint::bit_length(x) - 1;
  const std::uint64_t m = e >= 32 ? x >> (e - 32) : x << (32 - e);  // in [2^32, 2^33)
  const auto below = static_cast<std::uint32_t>(m);                // the bits after the leading one
  const std::uint32_t i = below >> 27, within = (below >> 11) & 0xFFFFu;
  const std::uint32_t lo = log2_q16_table[i], hi = log2_q16_table[i + 1];
  return e * 65536 + static_cast<std::int32_t>(lo + (((hi - lo) * within) >> 16));  // (hi - lo) < 2^12
}

// log2 (a^2 + b^2) in Q.16: twice the log of the length of (a, b), a or b nonzero.
constexpr std::int32_t log2_length2_q16(std::int64_t a, std::int64_t b) {
  const std::uint64_t ua = static_cast<std::uint64_t>(a < 0 ? -a : a), ub = static_cast<std::uint64_t>(b < 0 ? -b : b);
  const std::uint64_t larger = ua > ub ? ua : ub;
  const int k = fixedpoint::bit_length(larger) > 31 ? fixedpoint::bit_length(larger) - 31 : 0;
  const std::uint64_t sa = ua >> k, sb = ub >> k;  // < 2^31: the squares' sum below 2^63; relative error 2^-30
  return log2_q16(sa * sa + sb * sb) + 2 * k * 65536;
}

// The triangle's part of lambda, for trilinear objects.
struct LodPlanes {
  // Numerators (times 2^-shift): d/dx = b y_s + ax (per row), d/dy = b x_s + ay (per column),
  // [0] for u and [1] for v; x_s, y_s the pixel centre in subpixels.
  std::int64_t b[2], ax[2], ay[2];
  int e_shift;               // H sums E_i >> e_shift (E_i < 2^31 then)
  std::int32_t constant_q16; // twice the log of the constant factors (below), Q.16
  std::int32_t row_y;        // the current row's centre in subpixels (the caller sets it per row)
};

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
  const int shift = fixedpoint::bit_length(largest) > 36 ? fixedpoint::bit_length(largest) - 36 : 0;
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

// lambda (Q.8) at column c of the current row: the larger derivative length over
// H^2, H = sum E_i w_i (each E_i >> e_shift <= 2^31 inside, times w_i < 2^31: the
// sum fits 64 bits unsigned; it is at least D w_min, so the dropped bits are
// 2^-30 w_max / w_min of it). Four Q.16 logarithms (2^-12.3 each, the length's
// counted half) and the final rounding (2^-9): |error| < 2^-9 + 3.5 * 2^-12.3 < 2^-8.5
// against the exact lambda at that pixel centre.
constexpr std::int32_t lod_at(const LodPlanes& p, const TriangleSetup& t, std::int32_t column) {
  std::uint64_t h = 0;
  for (int i = 0; i < 3; ++i) {
    const std::int64_t e = t.edge[i].value_at(column);
    if (e > 0) h += fixedpoint::mul_u32(static_cast<std::uint32_t>(e >> p.e_shift), t.omega[i]);
  }
  if (h == 0) return lod_level_zero;
  const std::int64_t x_s = std::int64_t{column} * 256 + 128, y_s = p.row_y;
  const std::int64_t xu = p.b[0] * y_s + p.ax[0], xv = p.b[1] * y_s + p.ax[1];
  // d/dy's numerator has the opposite sign (x_m - x): lengths do not see it.
  const std::int64_t yu = p.b[0] * x_s + p.ay[0], yv = p.b[1] * x_s + p.ay[1];
  const bool flat_x = xu == 0 && xv == 0, flat_y = yu == 0 && yv == 0;
  if (flat_x && flat_y) return lod_level_zero;
  const std::int32_t along_x = flat_x ? INT32_MIN : log2_length2_q16(xu, xv);
  const std::int32_t along_y = flat_y ? INT32_MIN : log2_length2_q16(yu, yv);
  const std::int32_t twice_q16 = (along_x > along_y ? along_x : along_y) + p.constant_q16 - 4 * log2_q16(h);
  return (twice_q16 + 256) >> 9;  // / 2, to Q.8, rounded
}

// The lambda a run [column, run_end) holds, and where the run must end for
// its ends' lambdas to lie within lod_run_spread of each other.
inline constexpr std::int32_t lod_run_spread = 1 << (lod_frac_bits - 4);  // 1/16
struct RunLod {
  std::int32_t lod, run_end;
};
constexpr RunLod hold_lod(const LodPlanes& p, const TriangleSetup& t, std::int32_t column, std::int32_t run_end) {
  const std::int32_t first = lod_at(p, t, column);
  std::int32_t last = run_end - 1 > column ? lod_at(p, t, run_end - 1) : first;
  while (run_end - column > 1 && (last - first > lod_run_spread || first - last > lod_run_spread)) {
    run_end = column + (run_end - column) / 2;
    last = run_end - 1 > column ? lod_at(p, t, run_end - 1) : first;
  }
  return {static_cast<std::int32_t>((std::int64_t{first} + last) >> 1), run_end};
}

}  // namespace spanlight
