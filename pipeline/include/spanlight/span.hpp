// Stage 4b, spans: walk a row's covered columns. Each group (surface uv, each
// projector) is evaluated exactly (perspective.hpp, evaluate_group) at the
// span's two ends, and at subdivision points at most 2^span_log2 pixels apart
// in between: there from the 1-D perspective interpolation of the ends
// (RowInterpolation, one reciprocal) when q > 0 at both and no value is
// clamped, else by evaluate_group. Between subdivision points values step
// linearly (Quake's subdivision). A segment is halved while linear stepping
// would drift more than 2^-tolerance_log2 texel from the exact value, and
// evaluated at every pixel where a projector's q changes sign (q/w is linear
// on screen, so q > 0 at both ends means q > 0 all along).
//
// Each group keeps its own schedule, and depth steps by its own gradient, so a
// pixel's values do not depend on which other groups a pass interpolates: the
// multipass and the fused pass see the same numbers.
#pragma once

#include <cstdint>
#include <concepts>
#include <type_traits>

#include "spanlight/features.hpp"
#include "spanlight/perspective.hpp"
#include "spanlight/pixel_inline.hpp"

namespace spanlight {

template <int P>
struct PointValues {
  std::int32_t z;  // Q1.30
  std::int32_t u, v;
  std::int32_t s[P > 0 ? P : 1], t[P > 0 ? P : 1], r[P > 0 ? P : 1];  // Q3.28
  bool front[P > 0 ? P : 1];  // q > 0: in front of the projector
};

// What a pass needs interpolated: depth always; uv and a range of projectors on request.
struct SpanNeeds {
  bool uv;
  int projector_begin, projector_end;
};

struct SpanControl {
  int span_log2;
  int tolerance_log2;                     // 0: never shorten a segment
  int uv_frac_bits;                       // of the object being drawn
  const std::uint16_t* projector_texels;  // larger side of each projector's image
};

// The pixels between two events of a walk: the first one's values and what
// each further pixel adds. A kernel with a run() walks them itself, with its
// per-object choices made once per run instead of at every pixel.
template <int P>
struct PixelRun {
  PointValues<P> first;  // z is taken from z_acc
  std::int32_t du, dv;
  std::int32_t ds[P > 0 ? P : 1], dt[P > 0 ? P : 1], dr[P > 0 ? P : 1];
  std::int64_t z_acc, dzdx;  // depth, Q1.30 with 32 more fraction bits
};

// body(k, values) for pixels k = 0 .. count - 1 of a run (count >= 1), with
// the adds the walk would do; returns z_acc one pixel past the run.
template <int P, typename Body>
SPANLIGHT_PIXEL_INLINE std::int64_t for_each_run_pixel(const PixelRun<P>& run, std::int32_t count, Body&& body) {
  PointValues<P> v = run.first;
  std::int64_t z = run.z_acc;
  for (std::int32_t k = 0;;) {
    v.z = static_cast<std::int32_t>(z >> 32);
    body(k, v);
    z += run.dzdx;
    if (++k == count) return z;
    v.u += run.du;
    v.v += run.dv;
    for (int j = 0; j < P; ++j) {
      v.s[j] += run.ds[j];
      v.t[j] += run.dt[j];
      v.r[j] += run.dr[j];
    }
  }
}

// A walk's pixel function that walks whole runs itself (geometry.hpp's RowPixels for a kernel with run()).
template <typename Fn, int P>
concept RunsPixels = requires(Fn& f, const PixelRun<P>& r) {
  { f.run(std::int32_t{0}, std::int32_t{1}, r) } -> std::same_as<std::int64_t>;
};

// Linear stepping between two points deviates from the perspective-correct
// value by at most |delta texels| * |delta d| / (4 min d), d the screen-linear
// divisor (Heckbert & Moreton '91). Returns 0 when that exceeds
// 2^-tolerance_log2 texel, 1 when it is within, 2 when it is within a quarter
// of it: the deviation grows with the square of the length, so a segment twice
// as long is worth trying next. delta_texels8 has 8 fraction bits.
constexpr int linear_headroom(std::uint64_t delta_texels8, std::int64_t d0, std::int64_t d1, int tolerance_log2) {
  if (tolerance_log2 == 0 || d0 <= 0 || d1 <= 0) return 2;  // sign changes are handled per pixel
  const auto u0 = static_cast<std::uint64_t>(d0), u1 = static_cast<std::uint64_t>(d1);
  // Bring both below 2^31 by one shift; it is < 32 because divisors stay below 2^62 (perspective.hpp).
  const int excess = fixedpoint::bit_length(u0 > u1 ? u0 : u1) - 31;
  const int s = excess > 0 ? excess : 0;
  const std::uint32_t a = fixedpoint::low_word_shifted_right(u0, s), b = fixedpoint::low_word_shifted_right(u1, s);
  const std::uint32_t delta_d = a > b ? a - b : b - a;
  const std::uint32_t smaller = a < b ? a : b;
  const std::uint32_t texels = delta_texels8 > 0xFFFFFFFFu ? 0xFFFFFFFFu : static_cast<std::uint32_t>(delta_texels8);
  // |dt| * |dd| <= min * 2^(10 - tol) (tol <= 10, render_frame checks): left < 2^63, right < 2^41.
  const std::uint64_t drift = fixedpoint::mul_u32(texels, delta_d);
  const std::uint64_t allowed = fixedpoint::widened_shifted_left(smaller, 10 - tolerance_log2);
  return drift > allowed ? 0 : (drift <= allowed >> 2 ? 2 : 1);
}

// The texel distance between two points of a group, 8 fraction bits.
constexpr std::uint64_t texel_delta8(const GroupPoint& a, const GroupPoint& b, int group, const SpanControl& c) {
  const std::int64_t d0 = std::int64_t{b.value[0]} - a.value[0], d1 = std::int64_t{b.value[1]} - a.value[1];
  const std::uint64_t d = static_cast<std::uint64_t>(d0 < 0 ? -d0 : d0) + static_cast<std::uint64_t>(d1 < 0 ? -d1 : d1);
  if (group == uv_group) return c.uv_frac_bits >= 8 ? d >> (c.uv_frac_bits - 8) : d << (8 - c.uv_frac_bits);
  return (d * c.projector_texels[group]) >> (proj_frac_bits - 8);  // d < 2^32, size <= 2^12
}

// A value clamped at +-proj_limit is not the ratio any more, so stepping
// linearly from it is wrong unless both ends are clamped on the same side
// (q > 0 along the segment makes each ratio monotonic there: all of it is
// outside then).
constexpr bool saturation_breaks_linearity(const GroupPoint& a, const GroupPoint& b) {
  if (!a.front || !b.front) return false;  // sign changes go per pixel anyway
  for (int k = 0; k < 3; ++k) {
    const bool sa = a.value[k] == proj_limit || a.value[k] == -proj_limit;
    const bool sb = b.value[k] == proj_limit || b.value[k] == -proj_limit;
    if ((sa || sb) && a.value[k] != b.value[k]) return true;
  }
  return false;
}

constexpr std::int32_t step_of(std::int32_t from, std::int32_t to, std::int32_t length) {
  if (length == 1) return 0;  // never applied: the segment's end is taken as is
  const std::int32_t delta = to - from;  // both within +-2^30, and not -+2^30 both when length > 1
  return (length & (length - 1)) == 0 ? (delta >> (31 - fixedpoint::clz32(static_cast<std::uint32_t>(length))))
                                      : delta / length;
}

// One group's schedule along a span: the exact point it started from, the
// step to the next one, and the planning done there. The walk copies value
// and step into locals for the pixels between events (stores to the colour
// buffer may alias anything in memory; locals stay in registers).
template <int P, typename R>
struct GroupStepper {
  int group;
  std::int32_t value[3];
  bool front;
  std::int32_t step[3];
  std::int32_t segment_end;  // column of the segment's end point
  bool per_pixel;            // q changes sign inside this segment
  std::int32_t trial_length; // first length tried for the next segment

  constexpr void start(const TriangleSetup& t, const TriangleAttributes<P>& a, const SpanControl& c, int g,
                       std::int32_t c0, std::int32_t c1) {
    group = g;
    trial_length = 1 << c.span_log2;
    here = 0;
    interpolated = false;
    exact_at(t, a, c0, points[0]);
    if (c0 < c1) {
      exact_at(t, a, c1, points[1]);
      if (interpolable(points[0], points[1])) {  // the usual case: the rest of the row's points are cheap
        row.init(c0, c1, points[0], points[1]);
        interpolated = true;
        row.at<R>(c0, points[0]);  // the same values; the denominator on the row's scale
      }
    }
    take(points[0]);
    plan_or_finish(t, a, c, c0, c1);
  }

  // The next column at which this group needs out-of-line work, seen from `column`.
  constexpr std::int32_t next_event(std::int32_t column) const { return per_pixel ? column + 1 : segment_end; }

  // At next_event(): the segment's end (take it, plan the next) or, inside a
  // segment where q changes sign, the exact value at this pixel.
  [[gnu::noinline]] constexpr void arrive(const TriangleSetup& t, const TriangleAttributes<P>& a, const SpanControl& c,
                                          std::int32_t column, std::int32_t c1) {
    if (column == segment_end) {
      here ^= 1;  // the end is where the next segment starts: no copy
      take(points[here]);
      plan_or_finish(t, a, c, column, c1);
    } else {
      GroupPoint& scratch = points[here];  // the segment's start is not needed again
      point_at(t, a, column, scratch);
      take(scratch);
    }
  }

 private:
  // The exact points at the current segment's start (points[here]) and end
  // (points[here ^ 1]), kept in place: on ARMv6-M a struct copy is a call to memcpy.
  GroupPoint points[2];
  int here;
  RowInterpolation row;  // between the span's ends, when `interpolated`
  bool interpolated;

  constexpr void exact_at(const TriangleSetup& t, const TriangleAttributes<P>& a, std::int32_t column, GroupPoint& out) const {
    out = evaluate_group<P, R>(t, a, group, t.edge[1].value_at(column), t.edge[2].value_at(column));
  }
  constexpr void point_at(const TriangleSetup& t, const TriangleAttributes<P>& a, std::int32_t column, GroupPoint& out) const {
    if (interpolated) row.at<R>(column, out);
    else exact_at(t, a, column, out);
  }

  constexpr void take(const GroupPoint& p) {
    for (int k = 0; k < 3; ++k) value[k] = p.value[k];
    front = p.front;
  }

  constexpr void plan_or_finish(const TriangleSetup& t, const TriangleAttributes<P>& a, const SpanControl& c,
                                std::int32_t column, std::int32_t c1) {
    if (column < c1) {
      plan_segment(t, a, c, column, c1);
    } else {  // the span's last pixel: no event before the walk ends
      segment_end = c1 + 1;
      per_pixel = false;
    }
  }

  constexpr void plan_segment(const TriangleSetup& t, const TriangleAttributes<P>& a, const SpanControl& c,
                              std::int32_t column, std::int32_t c1) {
    // Start from the last segment's length, doubled when that one drifted
    // less than a quarter of the tolerance: the curvature that set it changes
    // slowly along a row, so most first trials are the segment.
    const GroupPoint& from = points[here];
    GroupPoint& end = points[here ^ 1];
    const std::int32_t span_len = 1 << c.span_log2;
    std::int32_t len = c1 - column < trial_length ? c1 - column : trial_length;
    int headroom = 2;
    for (;;) {  // halve until linear stepping is close enough
      point_at(t, a, column + len, end);
      if (len == 1) break;
      if (interpolated || !saturation_breaks_linearity(from, end)) {
        headroom = linear_headroom(texel_delta8(from, end, group, c), from.denominator, end.denominator, c.tolerance_log2);
        if (headroom > 0) break;
      }
      len = (len + 1) >> 1;
    }
    trial_length = headroom == 2 ? (2 * len < span_len ? 2 * len : span_len) : len;
    segment_end = column + len;
    per_pixel = from.front != end.front;
    for (int k = 0; k < 3; ++k) step[k] = per_pixel ? 0 : step_of(from.value[k], end.value[k], len);
  }
};

// Depth along a span: exact at the first pixel, then dz/dx per pixel (or
// exact at every pixel for triangles too thin for a gradient).
struct DepthStepper {
  // Q1.30 with 32 more fraction bits, rounded, at the span's first column.
  static constexpr std::int64_t start(const TriangleSetup& t, std::int32_t c0) {
    const std::int32_t z = exact(t, c0);
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(std::int64_t{z}) << 32) + (std::int64_t{1} << 31);
  }
  // Out of line and cold: the per-pixel loop keeps no edge values alive for it.
  [[gnu::noinline, gnu::cold]] static constexpr std::int32_t exact(const TriangleSetup& t, std::int32_t column) {
    return mix3(t.z0, t.dz1, t.dz2, barycentric(t, t.edge[1].value_at(column)), barycentric(t, t.edge[2].value_at(column)));
  }
};

// Walks columns [c0, c1] of one row. `pixel(column, values)` is the pass's
// kernel. UV and Projectors are fixed at compile time so that each pass gets a
// loop holding only what it steps: a depth pass steps depth alone.
//
// The walk runs from event to event: between two columns where some group
// needs an exact point, every value is a local stepped by one add per pixel.
template <int P, typename R, bool UV, bool Projectors, typename PixelFn>
inline void walk_span(const TriangleSetup& t, const TriangleAttributes<P>& a, const SpanNeeds& needs,
                      const SpanControl& control, std::int32_t c0, std::int32_t c1, PixelFn&& pixel) {
  constexpr int PS = P > 0 && Projectors ? P : 1;
  GroupStepper<P, R> uv;  // start() sets everything the walk reads
  if constexpr (UV) uv.start(t, a, control, uv_group, c0, c1);
  GroupStepper<P, R> projector[PS];
  const int j0 = needs.projector_begin, j1 = needs.projector_end;
  if constexpr (Projectors)
    for_each_projector<PS>(j0, j1, [&](int j) { projector[j].start(t, a, control, j, c0, c1); });

  const bool z_exact = t.depth_per_pixel;
  std::int64_t z_acc = DepthStepper::start(t, c0);
  PixelRun<P> run{};  // groups the walk does not step keep zero steps
  run.dzdx = t.dzdx;
  std::int32_t uv_event = 0;
  std::int32_t proj_event[PS] = {};

  std::int32_t column = c0;
  for (;;) {
    // Load the groups into the run; it ends at the first event.
    std::int32_t run_end = c1 + 1;
    if constexpr (UV) {
      uv_event = uv.next_event(column);
      if (uv_event < run_end) run_end = uv_event;
      run.first.u = uv.value[0];
      run.first.v = uv.value[1];
      run.du = uv.step[0];
      run.dv = uv.step[1];
    }
    if constexpr (Projectors) {
      for_each_projector<PS>(j0, j1, [&](int j) {
        const GroupStepper<P, R>& g = projector[j];
        proj_event[j] = g.next_event(column);
        if (proj_event[j] < run_end) run_end = proj_event[j];
        run.first.s[j] = g.value[0];
        run.first.t[j] = g.value[1];
        run.first.r[j] = g.value[2];
        run.first.front[j] = g.front;
        run.ds[j] = g.step[0];
        run.dt[j] = g.step[1];
        run.dr[j] = g.step[2];
      });
    }
    const std::int32_t count = run_end - column;
    run.z_acc = z_acc;
    bool done = false;
    if constexpr (RunsPixels<std::remove_reference_t<PixelFn>, P>) {
      if (!z_exact) {
        z_acc = pixel.run(column, count, run);
        done = true;
      }
    }
    if (!done) {
      z_acc = for_each_run_pixel(run, count, [&](std::int32_t k, PointValues<P>& v) SPANLIGHT_LAMBDA_INLINE {
        if (z_exact) v.z = DepthStepper::exact(t, column + k);
        pixel(column + k, v);
      });
    }
    column = run_end;
    if (column > c1) return;
    // Each group either has its event here or takes the run's steps.
    if constexpr (UV) {
      if (column == uv_event) {
        uv.arrive(t, a, control, column, c1);
      } else {
        uv.value[0] = run.first.u + count * run.du;
        uv.value[1] = run.first.v + count * run.dv;
      }
    }
    if constexpr (Projectors) {
      for_each_projector<PS>(j0, j1, [&](int j) {
        GroupStepper<P, R>& g = projector[j];
        if (column == proj_event[j]) {
          g.arrive(t, a, control, column, c1);
        } else {
          g.value[0] = run.first.s[j] + count * run.ds[j];
          g.value[1] = run.first.t[j] + count * run.dt[j];
          g.value[2] = run.first.r[j] + count * run.dr[j];
        }
      });
    }
  }
}

// Calls fn(bool_constant<UV>, bool_constant<Projectors>) with the walk shape
// `needs` asks for, instantiating only the shapes the caller allows.
template <bool AllowUV, bool AllowProjectors, typename Fn>
inline void with_walk_shape(const SpanNeeds& needs, Fn&& fn) {
  const bool uv = AllowUV && needs.uv;
  const bool projectors = AllowProjectors && needs.projector_begin < needs.projector_end;
  if constexpr (AllowUV && AllowProjectors) {
    if (uv && projectors) return fn(std::true_type{}, std::true_type{});
  }
  if constexpr (AllowUV) {
    if (uv) return fn(std::true_type{}, std::false_type{});
  }
  if constexpr (AllowProjectors) {
    if (projectors) return fn(std::false_type{}, std::true_type{});
  }
  fn(std::false_type{}, std::false_type{});
}

// The same walk with its shape chosen at run time from `needs` (tests, tools).
template <int P, typename R, typename PixelFn>
inline void walk_span(const TriangleSetup& t, const TriangleAttributes<P>& a, const SpanNeeds& needs,
                      const SpanControl& control, std::int32_t c0, std::int32_t c1, PixelFn&& pixel) {
  with_walk_shape<true, (P > 0)>(needs, [&](auto uv, auto projectors) {
    walk_span<P, R, decltype(uv)::value, decltype(projectors)::value>(t, a, needs, control, c0, c1, pixel);
  });
}

// The row loop: each row's covered columns from the three edges' half-planes.
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
