// Stage 3c, spans: walk a row's covered columns c0..c1. Each group (the surface
// uv, each projector) is evaluated exactly (exact.hpp) at the span's two ends,
// and in between at the ends and middles of segments 2^k pixels long, k chosen
// per segment from the closed-form bound of segments.hpp (the last one of a span
// may start before the current pixel and end at the span's end); there from the
// 1-D perspective interpolation of the span's ends (RowInterpolation, one
// reciprocal). Within a segment values step as the quadratic through those
// three points: two adds a pixel. A projector whose q changes sign inside the
// span is evaluated at every pixel; one that is behind (q <= 0) or outside its
// frustum along the whole span is held constant (q/w is linear on the row, and
// s/q, t/q, r/q are monotonic where q > 0).
//
// Depth is stepped by the triangle's dz/dx from the span's first pixel, and
// each group keeps its own schedule, so a pixel's values do not depend on
// which other groups a pass interpolates: the multipass and the fused pass see
// the same numbers.
//
// Values step in each group's own scale (StepScale): uv of a repeating texture
// in fractions of the texture's size, wrapping modulo 2^32 exactly as the
// texture repeats (so as many fraction bits as 32 bits allow), other uv in
// texels * 2^uv_frac_bits, projectors in Q3.28.
//
// The walk hands the pass's kernel runs of pixels between two events
// (PixelRun): the first pixel's values and how each further pixel moves them.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "spanlight/3_span/exact.hpp"
#include "spanlight/3_span/lod.hpp"
#include "spanlight/3_span/segments.hpp"
#include "spanlight/features.hpp"
#include "spanlight/knobs.hpp"

namespace spanlight {

// How a group's exact values (texels * 2^frac, or Q3.28) become stepping values:
// (value + offset) << shift, as a 32-bit pattern that may wrap.
struct StepScale {
  std::int32_t offset[3];
  std::uint8_t shift[3];
  std::uint8_t texel_bits;  // log2 of stepping units per texel (the smallest over the components)
};

// What a pass needs interpolated: depth always; uv (stepped in its sampler's
// scale) and a range of projectors on request.
struct SpanNeeds {
  bool uv;
  StepScale uv_scale;
  int projector_begin, projector_end;
  bool lod = false;  // the run's mip level (a trilinear texture)
};

struct SpanControl {
  int span_log2;                     // segments of at most 2^span_log2 pixels
  int tolerance_log2;                // 2^-T texel for the segments' bound (0: unbounded)
  const StepScale* uv;                // of the object being drawn
  int uv_frac_bits;                  // its exact uv's sub-texel bits
  const std::uint16_t* projector_texels;  // larger side of each projector's image
  const std::uint8_t* projector_texel_bits;  // log2 of Q3.28 units per texel of each projector's image
  std::uint32_t z_limit;             // DepthFormat::z_limit: the deepest a stepped depth may go
  const LodPlanes* lod = nullptr;    // the triangle's, when the object is trilinear
  MipRule mip = MipRule::trilinear;  // segment: one level per uv segment (Knobs::mip)
};

// One value along a run: at the first pixel, and how it moves per pixel
// (v += step; step += curve, both wrapping).
struct Stepped {
  std::uint32_t value, step, curve;
};

template <int P>
struct PixelRun {
  std::uint32_t z;  // Q0.32, at the first pixel
  std::int32_t dz;  // per pixel (wrapping add; the walk keeps the run within [0, z_limit])
  Stepped u, v;
  [[no_unique_address]] PerProjector<Stepped, P> s, t, r;  // Q3.28
  [[no_unique_address]] PerProjector<bool, P> front;       // q > 0 all along the run
  RunLevel level;                  // the run's mip levels and mix (trilinear objects; else zero)
};

// Once a run. At -Os GCC makes a 12-byte struct assignment a memcpy call (about
// 70 instructions on M0+), so it is copied field by field there; at -O2 the
// assignment is one load-multiple and one store-multiple (M7: 8 fewer a run).
[[gnu::always_inline]] constexpr void copy_stepped(Stepped& to, const Stepped& from) {
#if defined(__OPTIMIZE_SIZE__)
  to.value = from.value;
  to.step = from.step;
  to.curve = from.curve;
#else
  to = from;
#endif
}

// Advances a stepped value by `count` pixels: what `count` rounds of the kernel's adds give.
[[gnu::always_inline]] constexpr void advance(Stepped& x, std::uint32_t count) {
  x.value += count * x.step + (count * (count - 1) / 2) * x.curve;
  x.step += count * x.curve;
}

// The texel distance between two points of a group, 8 fraction bits (the largest component's).
constexpr std::uint64_t texel_delta8(const GroupPoint& a, const GroupPoint& b, int group, const SpanControl& c) {
  std::uint32_t d = 0;  // |b - a| < 2^32 for int32 values: a word
  const int components = group == uv_group ? 2 : 3;  // r/q is read at the shadow map's texels: as fine as the image's
  for (int k = 0; k < components; ++k) {
    const std::int64_t delta = std::int64_t{b.value[k]} - a.value[k];
    const auto m = static_cast<std::uint32_t>(delta < 0 ? -delta : delta);
    if (m > d) d = m;
  }
  if (group == uv_group) return d >> (c.uv_frac_bits - 8);  // uv_frac_bits >= 8
  return fixedpoint::mul_u32_u16(d, c.projector_texels[group]) >> (proj_frac_bits - 8);  // size <= 2^12
}

// Everything a group's walk needs of the triangle to evaluate it exactly at a column.
template <int P, typename Divide>
struct GroupSource {
  const TriangleSetup& t;
  const TriangleAttributes<P>& a;
  const Divide& divide;

  constexpr void exact_at(int group, std::int32_t column, GroupPoint& out) const {
    const ScreenWeights s = screen_weights(t, t.edge[1].value_at(column), t.edge[2].value_at(column));
    const Weights w = perspective_weights(t, s, divide);
    if (group == uv_group) uv_point(a, w, out);
    else projector_point(a, group, w, divide, out);
  }
};

enum class GroupMode : std::uint8_t { interpolated, constant, per_pixel };

// One group along a span: its stepping state from the current pixel, and the
// exact point that ends the segment. Components: 2 for uv, 3 for a projector's
// s, t, r (a constant, so the per-component loops unroll).
template <int Components>
struct GroupSpan {
  static constexpr int components = Components;
  Stepped value[static_cast<std::size_t>(Components)];
  bool front;
  GroupMode mode;
  std::int32_t segment_end;  // the column of the next exact point (c1 + 1: none before the span ends)
  StepScale scale;
  SegmentPlanner planner;    // each segment's length
  std::int32_t exact_start[static_cast<std::size_t>(Components)];  // the exact values at the current segment's start
  GroupPoint end;            // the exact point at segment_end
  GroupPoint last;           // the exact point at the span's end c1
  RowInterpolation<Components> row;

  template <int P, typename Divide>
  constexpr void start(const GroupSource<P, Divide>& src, int group, const SpanControl& c, const Weights& w0,
                       const Weights& w1, std::int32_t c0, std::int32_t c1) {
    scale = group == uv_group ? *c.uv : StepScale{{0, 0, 0}, {0, 0, 0}, c.projector_texel_bits[group]};
    // The first point is held in `end` (plan sets it before it is read), not in a point of this
    // frame's own: this frame sits under plan's at a frame's peak stack.
    GroupPoint& first = end;
    point_from(src, group, w0, first);
    if (c0 == c1) {
      take_constant(first, c1);
      return;
    }
    point_from(src, group, w1, last);
    if (!first.front && !last.front) {  // behind the projector all along (q/w is linear)
      take_constant(first, c1);
      return;
    }
    if (first.front != last.front) {  // q changes sign: every pixel exactly
      take_per_pixel(first, c0);
      return;
    }
    // q > 0 all along: s/q, t/q and r/q are monotonic along the row (ratios of linear functions
    // without a pole), so a projector outside one side at both exact ends is outside all along, up
    // to the ends' own errors (attribute_property_test checks every held pixel against that bound).
    if (group != uv_group && outside_all_along(first, last)) {
      take_constant(first, c1);
      return;
    }
    if (!interpolable(first, last)) {
      take_per_pixel(first, c0);
      return;
    }
    mode = GroupMode::interpolated;
    row.init(c0, c1, first, last);
    planner.start(c0, c1, row.e_a, row.e_b, texel_delta8(first, last, group, c), scale.texel_bits, c.tolerance_log2,
                  c.span_log2);
    take(first);
    plan(src.divide, c0, c1, planner.den(c0));
  }

  // At segment_end: take the exact point there and plan the next segment; in
  // per-pixel mode, evaluate this pixel exactly.
  template <int P, typename Divide>
  [[gnu::noinline]] constexpr void arrive(const GroupSource<P, Divide>& src, int group, std::int32_t column, std::int32_t c1) {
    if (mode == GroupMode::per_pixel) {  // `end` is free in this mode: it holds the pixel's point
      if (column == c1) end = last;
      else src.exact_at(group, column, end);
      take(end);
      segment_end = column + 1;
      return;
    }
    take(end);
    plan(src.divide, column, c1, static_cast<std::uint64_t>(end.denominator));  // end: RowInterpolation::at's point at column
  }

 private:
  // Both ends outside the same side of [0, 1] for one of s/q, t/q, r/q: outside all along.
  static constexpr bool outside_all_along(const GroupPoint& p, const GroupPoint& q) {
    constexpr std::int32_t one = std::int32_t{1} << proj_frac_bits;
    for (int k = 0; k < 3; ++k) {
      if ((p.value[k] < 0 && q.value[k] < 0) || (p.value[k] > one && q.value[k] > one)) return true;
    }
    return false;
  }

  template <int P, typename Divide>
  static constexpr void point_from(const GroupSource<P, Divide>& src, int group, const Weights& w, GroupPoint& out) {
    if (group == uv_group) uv_point(src.a, w, out);
    else projector_point(src.a, group, w, src.divide, out);
  }

  constexpr std::uint32_t scaled(const GroupPoint& p, int k) const {
    return static_cast<std::uint32_t>(p.value[k] + scale.offset[k]) << scale.shift[k];
  }
  constexpr void take(const GroupPoint& p) {
    for (int k = 0; k < components; ++k) {
      value[k] = {scaled(p, k), 0, 0};
      exact_start[k] = p.value[k];
    }
    front = p.front;
  }
  constexpr void take_constant(const GroupPoint& p, std::int32_t c1) {
    mode = GroupMode::constant;
    take(p);
    segment_end = c1 + 1;
  }
  constexpr void take_per_pixel(const GroupPoint& p, std::int32_t c0) {
    mode = GroupMode::per_pixel;
    take(p);
    segment_end = c0 + 1;
  }

  // The segment from `column` (its values taken, den_column the planner's den there) to the next exact point: the
  // planned power of two; where less than that is left, one segment back from the
  // span's end (plan_tail), else the largest power of two that fits before it.
  template <typename Divide>
  constexpr void plan(const Divide& divide, std::int32_t column, std::int32_t c1, std::uint64_t den_column) {
    if (column >= c1) {  // the span's last pixel
      segment_end = c1 + 1;
      return;
    }
    const std::int32_t left = c1 - column;
    int k = planner.length_log2_at(column, den_column);
    if ((std::int32_t{1} << k) > left && plan_tail(divide, column, c1, fixedpoint::bit_length(static_cast<std::uint32_t>(left - 1))))
      return;
    while ((std::int32_t{1} << k) > left) --k;
    segment_end = column + (std::int32_t{1} << k);
    if (segment_end == c1) end = last;
    else row.at(segment_end, divide, end);
    if (k == 0) return;  // one pixel: nothing steps
    GroupPoint middle;
    row.at(column + (std::int32_t{1} << (k - 1)), divide, middle);
    set_steps(exact_start, middle, end, k);
  }

  // The span's tail, `left` = c1 - column pixels fewer than the planned length, as one segment of
  // 2^k >= left pixels that ends at c1 and starts 2^k - left pixels back (still in the span), when
  // the bound allows 2^k there: two exact points (that start and the middle; the end is `last`) in
  // place of cutting the tail into its binary digits, a segment each. The stepped values at
  // `column` are the quadratic's there, within the same bound as any pixel of the segment.
  template <typename Divide>
  constexpr bool plan_tail(const Divide& divide, std::int32_t column, std::int32_t c1, int k) {
    const std::int32_t start = c1 - (std::int32_t{1} << k);
    if (start == column || start < planner.a || planner.length_log2_at(start) < k) return false;
    GroupPoint first, middle;
    row.at(start, divide, first);
    row.at(start + (std::int32_t{1} << (k - 1)), divide, middle);
    end = last;
    segment_end = c1;
    set_steps(first.value, middle, last, k);
    const auto back = static_cast<std::uint32_t>(column - start);
    for (int c = 0; c < components; ++c) {
      value[c].value = scaled(first, c);
      advance(value[c], back);  // exact modulo 2^32: what `back` rounds of the kernel's adds give
    }
    return true;
  }

  // The steps of the quadratic through the exact values at a segment's start, middle and end (k >= 1).
  constexpr void set_steps(const std::int32_t* start, const GroupPoint& middle, const GroupPoint& stop, int k) {
    for (int c = 0; c < components; ++c) {
      const QuadraticSteps q = quadratic_steps(middle.value[c] - start[c], stop.value[c] - middle.value[c], k, scale.shift[c]);
      value[c].step = q.step;
      value[c].curve = q.curve;
    }
  }
};

// Walks columns [c0, c1] of one row, calling run_pixels(first column, count,
// PixelRun) for runs between events. UV and Projectors are fixed at compile
// time so that each pass steps only what it reads: a depth pass steps depth alone;
// Lod compiles the mip level's computation (a build with trilinear textures).
// `run` comes zeroed from the caller, once a triangle: the groups a shape does not
// step keep zero values and steps, and what it steps is set before every run.
// Out of line, one call a span: inlined into the triangle's shape dispatch, the
// shapes' group states (three projectors' are 600 bytes) piled up in one frame.
template <int P, bool UV, bool Projectors, bool Lod = false, typename Divide, typename RunFn>
[[gnu::noinline]] inline void walk_span(const TriangleSetup& t, const TriangleAttributes<P>& a, const SpanNeeds& needs,
                                        const SpanControl& control, const Divide& divide, std::int32_t c0,
                                        std::int32_t c1, PixelRun<P>& run, RunFn&& run_pixels) {
  constexpr int PS = Projectors ? P : 0;
  const GroupSource<P, Divide> src{t, a, divide};
  const ScreenWeights s0 = screen_weights(t, t.edge[1].value_at(c0), t.edge[2].value_at(c0));

  // Depth: exact at c0, then dz/dx. If the stepped depth could leave [0, z_limit]
  // (rounding at the near or far plane), or the triangle is too steep for dz/dx,
  // every pixel takes its exact depth, clamped.
  run.z = depth_q32(t, s0);
  run.dz = t.dzdx;
  bool z_exact = t.depth_per_pixel;
  if (!z_exact) {
    const std::int64_t z_end = std::int64_t{run.z} + std::int64_t{run.dz} * (c1 - c0);
    z_exact = run.z > control.z_limit || z_end < 0 || z_end > std::int64_t{control.z_limit};
  }

  GroupSpan<2> uv;
  PerProjector<GroupSpan<3>, PS> projector;
  const int j0 = needs.projector_begin, j1 = needs.projector_end;
  if constexpr (UV || Projectors) {
    const ScreenWeights s1 = screen_weights(t, t.edge[1].value_at(c1), t.edge[2].value_at(c1));
    const Weights w0 = perspective_weights(t, s0, divide), w1 = perspective_weights(t, s1, divide);
    if constexpr (UV) uv.start(src, uv_group, control, w0, w1, c0, c1);
    if constexpr (Projectors)
      for_each_projector<PS>(j0, j1, [&](int j) { projector[j].start(src, j, control, w0, w1, c0, c1); });
  }

  // lambda along the span, linear on pieces (3_span/lod.hpp); the first is planned at c0.
  // With MipRule::segment, one level is held until level_until, the end of its uv segment.
  LodPiece lod{c0, c0, 0, 0, 0};
  std::int32_t level_until = c0;
  if constexpr (UV && Lod) {
    if (control.lod != nullptr && control.mip == MipRule::trilinear) lod.end_value = lod_q16_at(*control.lod, t, c0);
  }

  std::int32_t column = c0;
  for (;;) {
    // The run ends at the first event of any group (or at the next pixel when depth goes per pixel).
    std::int32_t run_end = z_exact ? column + 1 : c1 + 1;
    if constexpr (UV) {
      if (uv.segment_end < run_end) run_end = uv.segment_end;
      copy_stepped(run.u, uv.value[0]);
      copy_stepped(run.v, uv.value[1]);
    }
    if constexpr (Projectors) {
      for_each_projector<PS>(j0, j1, [&](int j) {
        const GroupSpan<3>& g = projector[j];
        if (g.segment_end < run_end) run_end = g.segment_end;
        copy_stepped(run.s[j], g.value[0]);
        copy_stepped(run.t[j], g.value[1]);
        copy_stepped(run.r[j], g.value[2]);
        run.front[j] = g.front;
      });
    }
    if (z_exact) {
      const ScreenWeights s = screen_weights(t, t.edge[1].value_at(column), t.edge[2].value_at(column));
      const std::uint32_t z = depth_q32(t, s);
      run.z = std::min(z, control.z_limit);
    }
    std::int32_t count = run_end - column;
    if constexpr (UV && Lod) {
      if (control.lod != nullptr && control.mip == MipRule::segment) {
        if (column == level_until) {  // a new uv segment: runs never pass its end
          level_until = uv.segment_end < c1 + 1 ? uv.segment_end : c1 + 1;
          run.level = segment_level(*control.lod, t, column, level_until - 1);
        }
      } else if (control.lod != nullptr) {
        if (column == lod.end) lod = plan_lod_piece(*control.lod, t, column, lod.end_value, c1);  // runs never pass a piece's end
        if (run_end > lod.end) count = lod.end - column;
        run.level = run_level(lod.value + (column - lod.begin) * lod.step, lod.step, control.lod->last_level, count);
        run_end = column + count;
      }
    }
    run_pixels(column, count, run);
    if (run_end > c1) return;
    const auto n = static_cast<std::uint32_t>(count);
    run.z += static_cast<std::uint32_t>(run.dz) * n;  // wraps as count adds would
    // Each group either has its event here or moves on by the run's steps.
    if constexpr (UV) {
      if (run_end == uv.segment_end) {
        uv.arrive(src, uv_group, run_end, c1);
      } else {
        advance(uv.value[0], n);
        advance(uv.value[1], n);
      }
    }
    if constexpr (Projectors) {
      for_each_projector<PS>(j0, j1, [&](int j) {
        GroupSpan<3>& g = projector[j];
        if (run_end == g.segment_end) {
          g.arrive(src, j, run_end, c1);
        } else {
          for (int k = 0; k < 3; ++k) advance(g.value[k], n);
        }
      });
    }
    column = run_end;
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

// The row loop: each row's covered columns from the three edges' half-planes,
// for the rows of [band_begin, band_end) the triangle covers (the edges jump
// over the rows above the band). Inlined into each walk shape: out of line, its
// frame and walk_span's outgoing arguments were 88-96 bytes of the frame's peak
// stack, under the triangle's and above the walk's.
template <typename SpanFn>
[[gnu::always_inline]] inline void rasterize_rows(TriangleSetup& t, int width, std::int32_t band_begin, std::int32_t band_end, SpanFn&& span) {
  const std::int32_t first = std::max(t.row_begin, band_begin);
  const std::int32_t last = std::min(t.row_end, band_end);
  if (first > t.row_begin)
    for (Edge& e : t.edge) e.skip_rows(first - t.row_begin);
  for (std::int32_t row = first; row < last; ++row) {
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

// Every row of the triangle.
template <typename SpanFn>
inline void rasterize_rows(TriangleSetup& t, int width, SpanFn&& span) {
  rasterize_rows(t, width, t.row_begin, t.row_end, span);
}

}  // namespace spanlight
