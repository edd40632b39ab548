// Stage 3a, the exact perspective-correct value at one point of a triangle:
//
//   lambda_i = E_i / 2A                      (exact edge values, one multiply)
//   beta_i   = lambda_i w_i^-1 / sum(...)    (one reciprocal: the table + Newton knob)
//   uv       = sum beta_i uv_i
//   s/q, t/q, r/q = sum beta_i (s,t,r)_i / sum beta_i q_i   (one reciprocal per projector)
//
// The divisor for a projector is q, not the eye's 1/w (Segal et al., eq. 7).
// The weights are computed once per point and shared; values are computed per
// "group" (the surface uv, or one projector), so each group can be subdivided
// on its own schedule.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "spanlight/2_triangle/attributes.hpp"
#include "spanlight/2_triangle/setup.hpp"
#include "spanlight/3_span/divide.hpp"

namespace spanlight {


// base + (d1 b1 + d2 b2) / 2^30 for weights b in [0, 2^30] (barycentrics are clamped there, and
// the perspective ones are unsigned quotients): |d| < 2^31, each product < 2^61, the sum < 2^62.
constexpr std::int32_t mix3(std::int32_t base, std::int32_t d1, std::int32_t d2, std::int32_t b1, std::int32_t b2) {
  return static_cast<std::int32_t>(base + ((fixedpoint::mul_s32_nonnegative(d1, b1) + fixedpoint::mul_s32_nonnegative(d2, b2)) >> 30));
}

// n / d in Q3.28 given rcp = R::of(d) for a 32-bit d > 0, |n| < 2^31, saturated at +-proj_limit
// (2^30). The product p = n * mantissa has |p| < 2^62 and s = shift - 28 lies in [3, 34] (shift =
// 62 - clz32(d)). With hi = floor(p / 2^32): for s >= 32 the quotient floor(p / 2^s) is
// hi >> (s - 32), within [-2^30, 2^30), nothing to saturate; for s < 32, hi >> (s - 2) is the
// quotient's floor(/ 2^30): 0 or -1 puts it in [-2^30, 2^30), where it is the low word of p >> s,
// anything else beyond the limit of its sign. Word shifts only: a 64-bit shift by a run-time
// amount is a libgcc call on ARMv6-M.
constexpr std::int32_t divide_q28(std::int32_t n, const fixedpoint::Reciprocal& rcp) {
  const std::int64_t p = fixedpoint::mul_s32_u32(n, rcp.mantissa);
  const int s = rcp.shift - proj_frac_bits;
  const auto hi = static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::uint64_t>(p) >> 32));
  if (s >= 32) return hi >> (s - 32);  // arithmetic: floor
  const std::int32_t above = hi >> (s - 2);
  if (above > 0) return proj_limit;
  if (above < -1) return -proj_limit;
  return static_cast<std::int32_t>(fixedpoint::low_word_shifted_right(static_cast<std::uint64_t>(p), s));
}

// The screen barycentrics lambda_1, lambda_2 (Q0.30) at a point, from its exact edge values.
struct ScreenWeights {
  std::int32_t l1, l2;
};
constexpr ScreenWeights screen_weights(const TriangleSetup& t, std::int64_t e1, std::int64_t e2) {
  return {barycentric(t, e1), barycentric(t, e2)};
}

// Window depth in Q0.32 at a point: z0 + dz1 l1 + dz2 l2 (l in [0, 2^30]), with the products kept
// to Q.32 (|dz| <= 2^30, l <= 2^30: each < 2^60), clamped into [0, 2^32 - 1].
constexpr std::uint32_t depth_q32(const TriangleSetup& t, const ScreenWeights& w) {
  const std::int64_t z = (std::int64_t{t.z0} << 2) + ((fixedpoint::mul_s32_nonnegative(t.dz1, w.l1) + fixedpoint::mul_s32_nonnegative(t.dz2, w.l2)) >> 28);
  return static_cast<std::uint32_t>(std::clamp<std::int64_t>(z, 0, 0xFFFFFFFF));
}

// Perspective-correct barycentrics beta_1, beta_2 (Q0.30) and the
// screen-linear sum of lambda_i / w_i they were normalised by (the uv divisor).
struct Weights {
  std::int32_t b1, b2;
  std::uint32_t rho;
};

template <typename Divide>
constexpr Weights perspective_weights(const TriangleSetup& t, const ScreenWeights& s, const Divide& divide) {
  std::int32_t l0 = one_q30 - s.l1 - s.l2;
  if (l0 < 0) l0 = 0;
  // rho_i = lambda_i * w_i^-1, each < 2^30.
  const std::uint32_t rho0 = static_cast<std::uint32_t>(fixedpoint::mul_u32(std::uint32_t(l0), t.omega[0]) >> 31);
  const std::uint32_t rho1 = static_cast<std::uint32_t>(fixedpoint::mul_u32(std::uint32_t(s.l1), t.omega[1]) >> 31);
  const std::uint32_t rho2 = static_cast<std::uint32_t>(fixedpoint::mul_u32(std::uint32_t(s.l2), t.omega[2]) >> 31);
  const std::uint32_t sum = rho0 + rho1 + rho2;  // < 3 * 2^30
  if (sum == 0) return {s.l1, s.l2, 0};
  const fixedpoint::Reciprocal rcp = divide.of(sum);
  const int shift = rcp.shift - 30;  // >= 32 because sum < 2^32; beta <= 2^30 fits a word
  return {static_cast<std::int32_t>(fixedpoint::word_shifted_right(fixedpoint::mul_u32(rho1, rcp.mantissa), shift)),
          static_cast<std::int32_t>(fixedpoint::word_shifted_right(fixedpoint::mul_u32(rho2, rcp.mantissa), shift)), sum};
}

// One group's values at a point: the surface's (u, v) or a projector's
// (s/q, t/q, r/q); `denominator` is the group's screen-linear divisor
// (1/w, or q/w up to a constant) that the subdivision watches.
struct GroupPoint {
  std::int32_t value[3];
  bool front;                // q > 0 (always true for uv); here, so that the point packs in 24 bytes, not 32
  std::int64_t denominator;
};

inline constexpr int uv_group = -1;  // the group index of the surface's uv; projectors are 0..P-1

template <int P>
constexpr void uv_point(const TriangleAttributes<P>& a, const Weights& w, GroupPoint& out) {
  out.value[0] = mix3(a.u0, a.du1, a.du2, w.b1, w.b2);
  out.value[1] = mix3(a.v0, a.dv1, a.dv2, w.b1, w.b2);
  out.value[2] = 0;
  out.denominator = w.rho;
  out.front = true;
}

template <int P, typename Divide>
constexpr void projector_point(const TriangleAttributes<P>& a, int j, const Weights& w, const Divide& divide,
                               GroupPoint& out) {
  const std::int32_t q = mix3(a.proj0[j][3], a.proj_d1[j][3], a.proj_d2[j][3], w.b1, w.b2);
  out.denominator = fixedpoint::mul_s32_u32(q, w.rho);  // q/w up to the triangle's constant scale
  out.front = q > 0;
  if (q <= 0) {
    out.value[0] = out.value[1] = out.value[2] = -proj_limit;  // never inside [0, 1]
    return;
  }
  const fixedpoint::Reciprocal rcp = divide.of(static_cast<std::uint32_t>(q));  // one reciprocal, three products
  for (int c = 0; c < 3; ++c) out.value[c] = divide_q28(mix3(a.proj0[j][c], a.proj_d1[j][c], a.proj_d2[j][c], w.b1, w.b2), rcp);
}

// Between two exact points a < b of one row. The group's divisor E (1/w for
// uv, q/w for a projector, up to a constant) is linear in x, and so is each
// value's numerator f * E; when E > 0 at both ends, exactly
//
//   f(x) = f_a + (f_b - f_a) * gamma,   gamma = (x - a) E_b / ((b - x) E_a + (x - a) E_b)
//
// (the 1-D perspective-correct interpolation): one reciprocal and one product
// per value at each subdivision point, where an exact point needs edge values,
// barycentrics, three weights and two reciprocals. gamma is in [0, 1], so f
// stays between f_a and f_b: no clamp is ever reached inside.
//
// Error: num and den are cut to 32 bits together (2^-31 relative each), the
// reciprocal adds the divide's relative error e and the product a truncation of
// 2^-30, so |gamma error| <= gamma (e + 2^-30) + 2^-30 and the value is off by
// at most |f_b - f_a| (e + 2^-29) + 1 unit from the exact ratio of the ends.
template <int Components>  // 2 for uv, 3 for a projector's s, t, r
struct RowInterpolation {
  std::int32_t a, length;    // first column and b - a > 0
  std::uint32_t e_a, e_b;    // the divisors at a and b, scaled together below 2^31
  std::int32_t f_a[static_cast<std::size_t>(Components)], df[static_cast<std::size_t>(Components)];  // |f| < 2^30 at both ends, so |df| < 2^31

  constexpr void init(std::int32_t column_a, std::int32_t column_b, const GroupPoint& pa, const GroupPoint& pb) {
    a = column_a;
    length = column_b - column_a;
    const auto da = static_cast<std::uint64_t>(pa.denominator), db = static_cast<std::uint64_t>(pb.denominator);
    const int shift = std::max(fixedpoint::bit_length(std::max(da, db)) - 31, 0);
    e_a = static_cast<std::uint32_t>(da >> shift);
    e_b = static_cast<std::uint32_t>(db >> shift);
    for (int k = 0; k < Components; ++k) {
      f_a[k] = pa.value[k];
      df[k] = pb.value[k] - pa.value[k];
    }
  }

  // The point at column x in [a, b]; its denominator is (b - x) E_a + (x - a) E_b,
  // the divisor up to the row's constant (segment lengths compare ratios only). Fills the first
  // Components values.
  template <typename Divide>
  constexpr void at(std::int32_t x, const Divide& divide, GroupPoint& out) const {
    const auto before = static_cast<std::uint32_t>(x - a), after = static_cast<std::uint32_t>(length) - before;
    const std::uint64_t num = fixedpoint::mul_u32_u16(e_b, before);  // < 2^12 * 2^31 (spans < 2^13 px)
    const std::uint64_t den = num + fixedpoint::mul_u32_u16(e_a, after);
    out.denominator = static_cast<std::int64_t>(den);
    out.front = true;
    if (after == 0 || before == 0) {  // the ends themselves, exactly
      for (int k = 0; k < Components; ++k) out.value[k] = after == 0 ? f_a[k] + df[k] : f_a[k];
      return;
    }
    // Both cut to the 32 bits below den's leading one (den < 2^43, so n >= 21);
    // 1/den_top is then 2^62 / den_top and gamma the product's high word.
    const fixedpoint::NormalisedPair top = fixedpoint::normalised_pair(den, num);
    const auto gamma = static_cast<std::int32_t>(fixedpoint::mul_u32(top.y_top, divide.of_normalised(top.x_top)) >> 32);  // Q0.30
    for (int k = 0; k < Components; ++k) out.value[k] = f_a[k] + static_cast<std::int32_t>(fixedpoint::mul_s32_nonnegative(df[k], gamma) >> 30);
  }
};

// Whether two exact points of a group bound a row stretch RowInterpolation can
// fill: q > 0 at both (so all along: q/w is linear) and no value clamped.
constexpr bool interpolable(const GroupPoint& p, const GroupPoint& q) {
  if (!p.front || !q.front || p.denominator <= 0 || q.denominator <= 0) return false;
  for (int k = 0; k < 3; ++k) {
    if (p.value[k] <= -proj_limit || p.value[k] >= proj_limit || q.value[k] <= -proj_limit || q.value[k] >= proj_limit)
      return false;
  }
  return true;
}

}  // namespace spanlight
