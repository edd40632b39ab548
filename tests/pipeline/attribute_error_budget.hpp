// The fixed pipeline's error budget for the values the span walk hands a
// pixel (depth, uv, each projector's s/q and t/q), derived from the formats and
// divides of 1_vertex/project.hpp, 2_triangle/setup.hpp, 3_span/exact.hpp,
// segments.hpp and walk.hpp, as bounds a test can hold every pixel to.
//
// Against what: the float model's perspective-correct values at the same pixel
// centre, on the pipeline's own snapped vertices and the very inputs prepare
// gave the pipeline (Q15.16 positions, block-float matrices and uv in texels *
// 2^uv_frac_bits, read back exactly). Snapping and input quantisation are then
// common to both, and what is left is the pipeline's arithmetic:
//   - 1/w per vertex (w >> k to 28 bits, reciprocal<8, 2>), normalised to the
//     nearest vertex and shifted (omega);
//   - Q0.30 screen barycentrics, the Q0.30 perspective weights and their divide
//     (the table/Newton knob), mix3's floor;
//   - per projector one more divide, by q, and the shift that brings (s,t,r,q) below 2^30;
//   - inside a span, RowInterpolation points from its two exact ends, and between them
//     quadratic steps (the segment bound 2^-T and the steps' rounding);
//   - depth: exact at a span's first pixel, then dz/dx (Q0.32) per pixel.
// Units: "lsb" is 2^-30 (Q0.30 weights and depth); "texel" is a texel of the
// image the value indexes (for a projector, of its image's larger side, as walk.hpp counts).
#pragma once

#include <algorithm>
#include <cmath>

#include "../fixedpoint/reciprocal_error.hpp"

namespace spanlight::ptest::budget {

inline constexpr double lsb = 0x1p-30;

// Relative error of the reciprocal with this table and Newton steps, 32-bit input (docs/reciprocal.md).
inline double reciprocal_relative(int table_bits, int newton_steps) {
  return static_cast<double>(reciprocal_error::bound_u32(table_bits, newton_steps));
}

// |lambda_i(fixed) - lambda_i| in lsb (barycentric()): e >> area_shift loses < 1 (times
// area_rcp / 2^32 <= 1), area_rcp's floor < e_norm / 2^32 <= 1/2, the final shift < 1, and
// D >> area_shift's own truncation < lambda * 2^30 * 2^-30 <= 1: 3.5 for lambda_1 and lambda_2,
// twice that for lambda_0 = 1 - lambda_1 - lambda_2. Clamping to [0, 1] only moves them closer.
inline constexpr double lambda_error_lsb(int vertex) { return vertex == 0 ? 7.0 : 3.5; }

// Relative error of omega_i against the reference's 1/w_i: w >> k keeps 28 bits (< 2^-27),
// the vertex divide's reciprocal<8, 2>, and the clip transform's rounding of w to Q31.32 (half
// a unit of 2^-32, at most 0.5 / (w_min 2^32) relative).
inline double omega_relative(double w_min) {
  return 0x1p-27 + reciprocal_relative(8, 2) + 0.5 / (w_min * 0x1p32);
}

// The perspective weights at one pixel (perspective_weights()). Exactly, rho_i = lambda_i
// omega_i / 2^31 (in lsb) with omega_i ~ 1/w_i scaled so that the largest is in [2^30, 2^31):
// omega_i / 2^31 <= (w_min / w_i)(1 + 2 eps_omega) =: share_i. The fixed rho_i = r_i + D_i with
//   |D_i| <= eps_omega r_i + c_i,  c_i = lambda's error * share_i + 1 (the product's floor)
//                                        + 1/2 (omega's own shift, times lambda <= 1).
// The fixed sum S = sum rho_i is bounded below from the reference: the nearest vertex's omega is
// >= 2^30 (1 - eps_omega), so S >= 2^29 (1 - 3 eps_omega) sum lambda_i w_min / w_i - sum c_i.
struct Weights {
  double eps_omega, eps_reciprocal;
  double c[3];               // the D_i bound's absolute part, lsb
  double sum_low;            // lower bound of S, lsb
  double beta;               // |b_i / 2^30 - beta_i|: (c_i + sum c) / S + 4 eps_omega + eps_R + 1 lsb
  double divisor_relative;   // |S - S_r| / S_r: the uv group's screen-linear divisor
};

inline Weights weights(const double (&lambda)[3], const double (&w)[3], double eps_omega, double eps_reciprocal) {
  Weights e{};
  e.eps_omega = eps_omega;
  e.eps_reciprocal = eps_reciprocal;
  const double w_min = std::min({w[0], w[1], w[2]});
  double sum = 0.0, c_sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    e.c[i] = lambda_error_lsb(i) * (w_min / w[i]) * (1.0 + 2.0 * eps_omega) + 1.5;
    sum += lambda[i] * w_min / w[i];
    c_sum += e.c[i];
  }
  e.sum_low = 0x1p29 * (1.0 - 3.0 * eps_omega) * sum - c_sum;
  const double c_max = std::max({e.c[0], e.c[1], e.c[2]});
  e.beta = (c_max + c_sum) / e.sum_low + 4.0 * eps_omega + eps_reciprocal + lsb;
  e.divisor_relative = eps_omega + c_sum / e.sum_low;
  return e;
}

// What the weights do to a value x interpolated at an exact point (mix3 on x_0 and the deltas):
// with x the exact value and x~ = sum x_i rho_i / S,
//   x~ - x = sum_i x_i (rho_i / S - beta_i) = sum_i D_i (x_i - x) / S
// (sum_i (rho_i / S - beta_i) = 0), so |x~ - x| <= 2 eps_omega max |x_i - x| + sum c_i |x_i - x| / S
// (r_i / S <= 2 beta_i while S >= S_r / 2, true while S_low is far above sum c; the test checks S_low >= 2^13).
// Then the divide b_i = rho_i / S (1 - e) - floor gives x_0 + (1 - e)(x~ - x_0) - floors:
// eps_R |x~ - x_0| more, and (|dx_1| + |dx_2|) lsb for the floors of b_1, b_2.
inline double weighted_value_error(const double (&x)[3], double value, const Weights& w) {
  double spread = 0.0, by_c = 0.0;
  for (int i = 0; i < 3; ++i) {
    spread = std::max(spread, std::fabs(x[i] - value));
    by_c += w.c[i] * std::fabs(x[i] - value);
  }
  const double weights_part = 2.0 * w.eps_omega * spread + by_c / w.sum_low;
  return weights_part + w.eps_reciprocal * (std::fabs(value - x[0]) + weights_part) +
         (std::fabs(x[1] - x[0]) + std::fabs(x[2] - x[0])) * lsb;
}

// uv at an exact point: u = u0 + (du1 b1 + du2 b2) >> 30 (mix3) on the prepared uvs, which the
// reference uses as they are: the weights' error and the floor's 2^-uv_frac_bits.
inline double uv_exact(const double (&u)[3], double u_value, const Weights& w, int uv_frac_bits) {
  return weighted_value_error(u, u_value, w) + std::ldexp(1.0, -uv_frac_bits);
}

// One projector at an exact point, for s/q (t/q alike), in the reference's units; `unit` =
// 2^(shift - 32) is the value of one unit after set_projector() (2_triangle/attributes.hpp)'s shift. Each vertex value is
// off by < 1.5 units (the shift's floor, the Q31.32 rounding), weighted by sum |b_i| <= 1 + 4 beta,
// and mix3 floors once more:
//   |s~ - s| <= weighted_value_error(s) + (1.5 (1 + 4 beta) + 1) unit, and the same for q.
// Then |s~/q~ - s/q| <= (ds + |s/q| dq) / (q - dq) while dq < q, and the divide by q~ adds eps_R
// of the quotient and its floor, 2^-28. Both renderers' values are taken clamped to +-4
// (proj_limit): clamping never increases a difference, and with |s/q| replaced by
// min(|s/q|, 4) the bound still holds for the clamped values (if s/q >= 4 > s~/q~, then
// 4 - s~/q~ <= (4 dq + ds) / q~). Returns < 0 where dq >= q: there q~ may be <= 0, the pixel
// legitimately counts as behind the projector, and nothing is promised about its value.
struct ProjectorPoint {
  double s[3], t[3], q[3];  // the vertices' values
  double unit;
  double s_value, t_value, q_value;  // interpolated (s, t and q, not the ratios)
};

inline double vertex_value_error(const double (&x)[3], double value, double unit, const Weights& w) {
  return weighted_value_error(x, value, w) + (1.5 * (1.0 + 4.0 * w.beta) + 1.0) * unit;
}

inline double q_error(const ProjectorPoint& p, const Weights& w) { return vertex_value_error(p.q, p.q_value, p.unit, w); }

inline double projector_exact(const ProjectorPoint& p, const Weights& w) {
  const double dq = q_error(p, w);
  if (!(dq < p.q_value)) return -1.0;
  auto one = [&](const double (&x)[3], double x_value) {
    const double m = std::min(std::fabs(x_value / p.q_value), 4.0);
    const double quotient = (vertex_value_error(x, x_value, p.unit, w) + m * dq) / (p.q_value - dq);
    return quotient + w.eps_reciprocal * (m + quotient) / (1.0 - w.eps_reciprocal) + 0x1p-28;
  };
  return std::max(one(p.s, p.s_value), one(p.t, p.t_value));
}

// Window depth in Q0.32 units (2^-32), at a pixel `steps` pixels after its span's first.
//  Vertex (project()): (z + w) / w with both >> k (w >> k >= 2^27) is off by < 2 / (2^27 - 1),
//  the reciprocal<8, 2> by 2 eps (the ratio is <= 2), the product's floor 2^-32, and the clip
//  transform's rounding of z and w by 2 / (w_min 2^32); halved to Q1.30, plus half an lsb (2^-30),
//  times 4 in Q0.32.
//  Span start (depth_q32): lambda_1, lambda_2 (3.5 lsb each, times |dz| <= 1: 14 units each) and
//  the product's floor (1 unit).
//  Steps (setup_triangle's dzdx, Q0.32 a pixel): the floor of mul_shift_wide and what num >> pre
//  drops (< 1 + 1/4 unit a pixel), and the relative error of 4/D (area_rcp's reciprocal<8, 2>,
//  d_norm's truncation 2^-31, the halving's floor 2^-30) over the depth the steps cover (< 2^32 units).
inline double depth_units(double w_min, int steps) {
  const double ratio = 2.0 / (0x1p27 - 1.0) + 2.0 * reciprocal_relative(8, 2) + 0x1p-32 + 2.0 / (w_min * 0x1p32);
  const double vertex = 4.0 * (ratio / 2.0 / lsb + 0.5);
  return vertex + 2.0 * 14.0 + 1.0 + 1.25 * steps + 0x1p32 * (reciprocal_relative(8, 2) + 0x1p-31 + 0x1p-30);
}

// A subdivision point inside a span whose two ends are exact points and fill it
// (3_span/exact.hpp, RowInterpolation: q > 0 at both ends and no value clamped):
// f~ = f_a~ + (f_b~ - f_a~) gamma~ with gamma~ from the ends' divisors. Against the truth
// f = f_a + (f_b - f_a) gamma:
//   f~ - f = (f_a~ - f_a)(1 - gamma~) + (f_b~ - f_b) gamma~ + (f_b - f_a)(gamma~ - gamma) + floor,
// so |f~ - f| <= max(E_a, E_b)(1 + 2 eps_R) + (|f_b~ - f_a~| + E_a + E_b) eps_gamma + 1 unit
// (gamma~ may pass 1 by eps_R without a Newton step). eps_gamma = |gamma~ - gamma|: the ends'
// divisors off by the relative d_a, d_b (the pipeline's own error and RowInterpolation::init's
// shift below 2^31) move gamma = b E_b / (a E_a + b E_b) by at most
// gamma (1 - gamma)(d_a + d_b) / (1 - max d) <= (d_a + d_b) / (4 (1 - max d)); num and den cut to
// 32 bits (2^-31 relative each), the reciprocal (eps_R) and the product's floor (2^-30) add
// gamma (eps_R + 2^-30)(1 + eps_R) + 2^-30.
inline double row_interpolated(double end_a, double end_b, double delta, double d_a, double d_b, double eps_reciprocal,
                               double unit) {
  const double eps_gamma = (d_a + d_b) / (4.0 * (1.0 - std::max(d_a, d_b))) +
                           (eps_reciprocal + 0x1p-30) * (1.0 + eps_reciprocal) + 0x1p-30;
  return std::max(end_a, end_b) * (1.0 + 2.0 * eps_reciprocal) + (delta + end_a + end_b) * eps_gamma + unit;
}

// A pixel inside a span whose ends are exact points and which the walk interpolates
// (walk.hpp: q > 0 at both ends, no value clamped). Let f be the true curve, f~ the 1-D
// perspective interpolation of the fixed ends with RowInterpolation's divisors, and Q the
// quadratic a segment steps (segments.hpp) through its start, middle and end, which are
// RowInterpolation points (or the span's exact ends). Then at a pixel
//   stepped - f = (stepped - Q~) + (Q~ - Q[f~]) + (Q[f~] - f~) + (f~ - f):
//   - the rounded steps drift at most 2^(2k-1) step units over 2^k pixels, which the planner's
//     rounding cap keeps within 2^-(T+1) texel;
//   - each node is f~ up to RowInterpolation's own rounding, |F~| (eps_R + 2^-29) + 1 unit
//     (exact.hpp), and the quadratic through three equally spaced nodes moves at most 1.25
//     times its nodes' errors (the Lebesgue constant of the three points on their interval);
//   - SegmentPlanner keeps the quadratic through f~'s own values within 2^-T texel of f~
//     (segments.hpp, bound (1));
//   - |f~ - f| <= row_interpolated() (which bounds the RowInterpolation point itself, so also
//     the exact curve through the fixed ends).
// At span 1 (stepping false) every pixel is a RowInterpolation point: row_interpolated() alone.
// Values in texels; `unit` the exact value's unit in texels; `delta` >= |f_b~ - f_a~|.
inline double interpolated_span(double end_a, double end_b, double delta, double d_a, double d_b, double eps_reciprocal,
                                double unit, bool stepping, int tolerance_log2) {
  const double points = row_interpolated(end_a, end_b, delta, d_a, d_b, eps_reciprocal, unit);
  if (!stepping) return points;
  const double node = delta * (eps_reciprocal + 0x1p-29) + unit;
  return points + 1.25 * node + std::ldexp(1.0, -tolerance_log2) + std::ldexp(1.0, -(tolerance_log2 + 1));
}

}  // namespace spanlight::ptest::budget
