// Stage 4, spans: walk a row's covered columns, evaluating the exact
// perspective-correct values every 2^span_log2 pixels and stepping them
// linearly in between (Quake's subdivision). At each subdivision point:
//
//   lambda_i = E_i / 2A                      (exact edge values, one multiply)
//   beta_i   = lambda_i w_i^-1 / sum(...)    (one reciprocal: the table + Newton knob)
//   uv       = sum beta_i uv_i
//   s/q, t/q, r/q = sum beta_i (s,t,r)_i / sum beta_i q_i   (one reciprocal per projector)
//
// q/w is linear in screen space, so when q > 0 at both ends of a segment it is
// > 0 all along; a segment where q changes sign is evaluated at every pixel.
#pragma once

#include <cstdint>

#include "spanlight/setup.hpp"

namespace spanlight {

inline constexpr int proj_frac_bits = 28;                 // s/q, t/q, r/q in Q3.28
inline constexpr std::int32_t proj_limit = 1 << 30;       // saturate at +-4: far outside [0, 1]
inline constexpr std::int32_t one_q30 = 1 << 30;

template <int P>
struct TriangleAttributes {
  std::int32_t u0, du1, du2, v0, dv1, dv2;  // rebased texel coordinates * 2^uv_frac_bits
  // per projector: (s, t, r, q) at vertex 0 and the deltas, normalised so |value| < 2^30
  std::int32_t proj0[P > 0 ? P : 1][4];
  std::int32_t proj_d1[P > 0 ? P : 1][4];
  std::int32_t proj_d2[P > 0 ? P : 1][4];
};

template <int P>
struct PointValues {
  std::int32_t z;  // Q1.30, set per pixel by the depth stepper
  std::int32_t u, v;
  std::int32_t s[P > 0 ? P : 1], t[P > 0 ? P : 1], r[P > 0 ? P : 1];  // Q3.28
  bool front[P > 0 ? P : 1];  // q > 0: in front of the projector
  // The screen-linear denominators, for the adaptive subdivision: sum of
  // lambda_i / w_i (normalised), and q = sum beta_i q_i per projector.
  std::uint32_t rho;
  std::int32_t q[P > 0 ? P : 1];
};

// What a pass needs interpolated: depth always; uv and a range of projectors on request.
struct SpanNeeds {
  bool uv;
  int projector_begin, projector_end;
};

// How a span is cut: at most 2^span_log2 pixels per segment, and shorter
// where stepping linearly would drift more than 2^-tolerance_log2 texel from
// the perspective-correct value (0: never shorter).
struct SpanControl {
  int span_log2;
  int tolerance_log2;
  int uv_frac_bits;                      // of the object being drawn
  const std::uint16_t* projector_texels;  // larger side of each projector's image
};

constexpr std::int32_t mix3(std::int32_t base, std::int32_t d1, std::int32_t d2, std::int32_t b1, std::int32_t b2) {
  // |d| < 2^31, b <= 2^30: each product < 2^61, the sum < 2^62.
  return static_cast<std::int32_t>(base + ((std::int64_t{d1} * b1 + std::int64_t{d2} * b2) >> 30));
}

constexpr std::int32_t saturate_proj(std::int64_t x) {
  return x > proj_limit ? proj_limit : (x < -proj_limit ? -proj_limit : static_cast<std::int32_t>(x));
}

// n / d in Q3.28 for d > 0, |n| < 2^31: n * mantissa < 2^62.
template <typename R>
constexpr std::int32_t divide_q28(std::int32_t n, std::uint32_t d) {
  const fixedpoint::Reciprocal rcp = R::of(d);
  return saturate_proj((std::int64_t{n} * rcp.mantissa) >> (rcp.shift - proj_frac_bits));
}

template <int P, typename R>
constexpr void evaluate_point(const TriangleSetup& t, const TriangleAttributes<P>& a, const SpanNeeds& needs,
                              std::int64_t e1, std::int64_t e2, PointValues<P>& out) {
  if (!needs.uv && needs.projector_begin >= needs.projector_end) return;
  const std::int32_t l1 = barycentric(t, e1);
  const std::int32_t l2 = barycentric(t, e2);
  std::int32_t l0 = one_q30 - l1 - l2;
  if (l0 < 0) l0 = 0;

  // Perspective-correct weights: rho_i = lambda_i * w_i^-1 (< 2^30 each).
  const std::uint32_t rho0 = static_cast<std::uint32_t>((std::uint64_t(std::uint32_t(l0)) * t.omega[0]) >> 31);
  const std::uint32_t rho1 = static_cast<std::uint32_t>((std::uint64_t(std::uint32_t(l1)) * t.omega[1]) >> 31);
  const std::uint32_t rho2 = static_cast<std::uint32_t>((std::uint64_t(std::uint32_t(l2)) * t.omega[2]) >> 31);
  const std::uint32_t sum = rho0 + rho1 + rho2;  // < 3 * 2^30
  out.rho = sum;
  std::int32_t b1 = l1, b2 = l2;
  if (sum != 0) {
    const fixedpoint::Reciprocal rcp = R::of(sum);
    const int shift = rcp.shift - 30;  // >= 32: sum < 2^32
    b1 = static_cast<std::int32_t>((std::uint64_t{rho1} * rcp.mantissa) >> shift);
    b2 = static_cast<std::int32_t>((std::uint64_t{rho2} * rcp.mantissa) >> shift);
  }
  if (needs.uv) {
    out.u = mix3(a.u0, a.du1, a.du2, b1, b2);
    out.v = mix3(a.v0, a.dv1, a.dv2, b1, b2);
  }
  for (int j = needs.projector_begin; j < needs.projector_end; ++j) {
    const std::int32_t q = mix3(a.proj0[j][3], a.proj_d1[j][3], a.proj_d2[j][3], b1, b2);
    out.front[j] = q > 0;
    out.q[j] = q;
    if (q <= 0) {
      out.s[j] = out.t[j] = out.r[j] = -proj_limit;  // never inside [0, 1]
      continue;
    }
    const auto d = static_cast<std::uint32_t>(q);
    out.s[j] = divide_q28<R>(mix3(a.proj0[j][0], a.proj_d1[j][0], a.proj_d2[j][0], b1, b2), d);
    out.t[j] = divide_q28<R>(mix3(a.proj0[j][1], a.proj_d1[j][1], a.proj_d2[j][1], b1, b2), d);
    out.r[j] = divide_q28<R>(mix3(a.proj0[j][2], a.proj_d1[j][2], a.proj_d2[j][2], b1, b2), d);
  }
}

// Per-pixel steps between two subdivision points `length` pixels apart.
template <int P>
struct PointSteps {
  std::int32_t u, v;
  std::int32_t s[P > 0 ? P : 1], t[P > 0 ? P : 1], r[P > 0 ? P : 1];
};

constexpr std::int32_t step_of(std::int32_t from, std::int32_t to, int length, int length_log2) {
  const std::int32_t delta = to - from;  // both within +-2^30 or one triangle's uv range
  return length_log2 >= 0 ? (delta >> length_log2) : delta / length;
}

// Linear stepping between two points a segment apart deviates from the
// perspective-correct value by about |delta texels| * |delta d| / (4 min d),
// d the screen-linear denominator (Heckbert & Moreton). True when that is
// within 2^-tolerance_log2 texel. delta_texels8 has 8 fraction bits.
constexpr bool linear_enough(std::uint64_t delta_texels8, std::int64_t d0, std::int64_t d1, int tolerance_log2) {
  if (d0 <= 0 || d1 <= 0) return true;  // sign changes are handled per pixel
  const std::uint64_t larger = static_cast<std::uint64_t>(d0 > d1 ? d0 : d1);
  const int excess = fixedpoint::bit_length(larger) - 31;  // bring d below 2^31
  const int s = excess > 0 ? excess : 0;
  const std::uint64_t a = static_cast<std::uint64_t>(d0) >> s, b = static_cast<std::uint64_t>(d1) >> s;
  const std::uint64_t delta_d = a > b ? a - b : b - a;
  const std::uint64_t smaller = a < b ? a : b;
  if (delta_texels8 > 0xFFFFFFFFu) delta_texels8 = 0xFFFFFFFFu;
  // |dt| * |dd| / (4 min) <= 2^-tol texel, with dt in 1/256 texel:
  // |dt| * |dd| <= min * 2^(10 - tol).  Left < 2^63, right < 2^41.
  return delta_texels8 * delta_d <= (smaller << 10) >> tolerance_log2;
}

template <int P>
constexpr bool segment_linear_enough(const PointValues<P>& a, const PointValues<P>& b, const SpanNeeds& needs,
                                     const SpanControl& control) {
  if (control.tolerance_log2 == 0) return true;
  if (needs.uv) {
    const std::int64_t du = std::int64_t{b.u} - a.u, dv = std::int64_t{b.v} - a.v;
    std::uint64_t d = static_cast<std::uint64_t>(du < 0 ? -du : du) + static_cast<std::uint64_t>(dv < 0 ? -dv : dv);
    d = control.uv_frac_bits >= 8 ? d >> (control.uv_frac_bits - 8) : d << (8 - control.uv_frac_bits);
    if (!linear_enough(d, a.rho, b.rho, control.tolerance_log2)) return false;
  }
  for (int j = needs.projector_begin; j < needs.projector_end; ++j) {
    if (!a.front[j] || !b.front[j]) continue;
    const std::int64_t ds = std::int64_t{b.s[j]} - a.s[j], dt = std::int64_t{b.t[j]} - a.t[j];
    const std::uint64_t d = static_cast<std::uint64_t>((ds < 0 ? -ds : ds) + (dt < 0 ? -dt : dt));
    const std::uint64_t texels8 = (d * control.projector_texels[j]) >> (proj_frac_bits - 8);  // < 2^32 * 2^12
    if (!linear_enough(texels8, std::int64_t{a.q[j]} * a.rho, std::int64_t{b.q[j]} * b.rho, control.tolerance_log2))
      return false;
  }
  return true;
}

// Depth along a span: exact at the first pixel, then dz/dx per pixel (or
// exact at every pixel for triangles too thin for a gradient). Called for
// consecutive columns only.
struct DepthStepper {
  std::int64_t acc;         // Q1.30 with 32 more fraction bits
  std::int64_t e1, e2;      // edge values at the span start, for the exact path
  constexpr DepthStepper(const TriangleSetup& t, std::int64_t e1_start, std::int64_t e2_start)
      : acc(0), e1(e1_start), e2(e2_start) {
    const std::int32_t z = mix3(t.z0, t.dz1, t.dz2, barycentric(t, e1), barycentric(t, e2));
    acc = static_cast<std::int64_t>(static_cast<std::uint64_t>(std::int64_t{z}) << 32) + (std::int64_t{1} << 31);
  }
  constexpr std::int32_t at(const TriangleSetup& t, std::int32_t offset) {
    if (t.depth_per_pixel) {
      return mix3(t.z0, t.dz1, t.dz2, barycentric(t, e1 + t.edge[1].slope * offset),
                  barycentric(t, e2 + t.edge[2].slope * offset));
    }
    const auto z = static_cast<std::int32_t>(acc >> 32);
    acc += t.dzdx;
    return z;
  }
};

// Walks columns [c0, c1] of one row. `pixel(column, values)` is the pass's kernel.
template <int P, typename R, typename PixelFn>
inline void walk_span(const TriangleSetup& t, const TriangleAttributes<P>& a, const SpanNeeds& needs,
                      const SpanControl& control, std::int32_t c0, std::int32_t c1, PixelFn&& pixel) {
  const std::int32_t span_len = 1 << control.span_log2;
  std::int64_t e1 = t.edge[1].value_at(c0);
  std::int64_t e2 = t.edge[2].value_at(c0);
  DepthStepper depth(t, e1, e2);
  auto emit = [&](std::int32_t column, PointValues<P>& values) {
    values.z = depth.at(t, column - c0);
    pixel(column, values);
  };
  PointValues<P> cur{};
  evaluate_point<P, R>(t, a, needs, e1, e2, cur);
  std::int32_t c = c0;
  while (c < c1) {
    const std::int32_t remaining = c1 - c;
    std::int32_t len = remaining < span_len ? remaining : span_len;
    PointValues<P> next{};
    std::int64_t e1_next = 0, e2_next = 0;
    for (;;) {  // shorten the segment until linear stepping is close enough
      e1_next = e1 + t.edge[1].slope * len;
      e2_next = e2 + t.edge[2].slope * len;
      evaluate_point<P, R>(t, a, needs, e1_next, e2_next, next);
      if (len == 1 || segment_linear_enough(cur, next, needs, control)) break;
      len = (len + 1) >> 1;
    }
    const int len_log2 = (len & (len - 1)) == 0 ? 31 - fixedpoint::clz32(static_cast<std::uint32_t>(len)) : -1;

    bool sign_change = false;
    for (int j = needs.projector_begin; j < needs.projector_end; ++j) sign_change |= cur.front[j] != next.front[j];
    if (sign_change) {
      // q crosses zero inside this segment: exact values at every pixel.
      for (std::int32_t k = 0; k < len; ++k) {
        PointValues<P> here{};
        evaluate_point<P, R>(t, a, needs, e1 + t.edge[1].slope * k, e2 + t.edge[2].slope * k, here);
        emit(c + k, here);
      }
    } else {
      PointSteps<P> step{};
      if (needs.uv) {
        step.u = step_of(cur.u, next.u, len, len_log2);
        step.v = step_of(cur.v, next.v, len, len_log2);
      }
      for (int j = needs.projector_begin; j < needs.projector_end; ++j) {
        step.s[j] = step_of(cur.s[j], next.s[j], len, len_log2);
        step.t[j] = step_of(cur.t[j], next.t[j], len, len_log2);
        step.r[j] = step_of(cur.r[j], next.r[j], len, len_log2);
      }
      PointValues<P> here = cur;
      for (std::int32_t k = 0; k < len; ++k) {
        emit(c + k, here);
        if (needs.uv) {
          here.u += step.u;
          here.v += step.v;
        }
        for (int j = needs.projector_begin; j < needs.projector_end; ++j) {
          here.s[j] += step.s[j];
          here.t[j] += step.t[j];
          here.r[j] += step.r[j];
        }
      }
    }
    c += len;
    e1 = e1_next;
    e2 = e2_next;
    cur = next;
  }
  emit(c1, cur);
}

// Stage 4a, the row loop: each row's covered columns from the three edges.
template <typename SpanFn>
inline void rasterize_rows(TriangleSetup& t, int width, SpanFn&& span) {
  for (std::int32_t row = t.row_begin; row < t.row_end; ++row) {
    std::int64_t lo = 0, hi = width - 1;
    bool empty = false;
    for (const Edge& e : t.edge) {
      if (e.slope > 0) {
        if (-e.quotient > lo) lo = -e.quotient;
      } else if (e.slope < 0) {
        if (e.quotient < hi) hi = e.quotient;
      } else {
        empty |= e.row_value < e.bias;
      }
    }
    if (!empty && lo <= hi) span(row, static_cast<std::int32_t>(lo), static_cast<std::int32_t>(hi));
    for (Edge& e : t.edge) e.next_row();
  }
}

}  // namespace spanlight
