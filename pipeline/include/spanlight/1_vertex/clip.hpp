// Stage 1b, clip: homogeneous clipping in clip space (Sutherland-Hodgman).
// The near plane (z >= -w) keeps the divide away from w <= 0; the far plane
// (z <= w) matches OpenGL; the guard band (|x|, |y| <= G * w) keeps snapped
// screen coordinates below 2^21 subpixels so setup's int64 products never
// overflow (see setup.hpp). Every attribute is interpolated linearly in clip
// space, as the spec asks: uv and each projector's (s, t, r, q).
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/divide.hpp"
#include "spanlight/1_vertex/transform.hpp"
#include "spanlight/features.hpp"

namespace spanlight {

template <int MaxProjectors>
struct ClipVertex {
  Vec4Wide clip;
  std::int32_t u, v;
  [[no_unique_address]] PerProjector<Vec4Wide, MaxProjectors> proj;  // (s, t, r, q), Q31.32
};

// A triangle clipped by 6 planes has at most 3 + 6 vertices.
inline constexpr int max_clipped_vertices = 9;

template <int MaxProjectors>
struct ClipPolygon {
  ClipVertex<MaxProjectors> v[max_clipped_vertices];
  int count = 0;
};

// Signed distance to a plane; inside when >= 0. The planes are linear in clip
// coordinates, so the distance along an edge is linear in the edge parameter.
enum class ClipPlane : std::uint8_t { near, far, left, right, bottom, top };

// The guard planes' G w / 4 for guard G in [1, 6] (draw.hpp: guard_band): a 32 x 16 product,
// no __muldi3 on ARMv6-M. Computed once for the planes of a point.
constexpr std::int64_t guard_w(const Vec4Wide& c, std::int64_t guard) {
  return fixedpoint::mul_s64_u16(c.w >> 2, static_cast<std::uint32_t>(guard));
}
constexpr std::int64_t plane_distance_with(ClipPlane plane, const Vec4Wide& c, std::int64_t gw) {
  switch (plane) {
    case ClipPlane::near: return c.z + c.w;
    case ClipPlane::far: return c.w - c.z;
    case ClipPlane::left: return gw + (c.x >> 2);
    case ClipPlane::right: return gw - (c.x >> 2);
    case ClipPlane::bottom: return gw + (c.y >> 2);
    case ClipPlane::top: return gw - (c.y >> 2);
  }
  return 0;
}
constexpr std::int64_t plane_distance(ClipPlane plane, const Vec4Wide& c, std::int64_t guard) {
  return plane_distance_with(plane, c, guard_w(c, guard));
}

// a + (b - a) * t, t in Q2.30 within [0, 1]. |b - a| < 2^62 holds for clip
// values bounded by the transform (< 2^61).
constexpr std::int64_t lerp_wide(std::int64_t a, std::int64_t b, std::int32_t t) {
  return a + fixedpoint::mul_shift_wide(b - a, t, 30);
}

constexpr Vec4Wide lerp_wide(const Vec4Wide& a, const Vec4Wide& b, std::int32_t t) {
  return {lerp_wide(a.x, b.x, t), lerp_wide(a.y, b.y, t), lerp_wide(a.z, b.z, t), lerp_wide(a.w, b.w, t)};
}

// The edge parameter where the distance crosses zero: da / (da - db) in Q2.30,
// da >= 0 > db. Both are shifted down together until the divisor fits 32 bits,
// which keeps the ratio to 2^-31 relative (one exact 64/32 division per cut).
constexpr std::int32_t crossing(std::int64_t da, std::int64_t db) {
  std::int64_t num = da;
  std::int64_t den = da - db;  // > 0
  const int excess = fixedpoint::bit_length(static_cast<std::uint64_t>(den)) - 32;
  if (excess > 0) {
    num >>= excess;                    // rounded down and
    den = ((den - 1) >> excess) + 1;   // rounded up: t never passes the plane
  }
  // 0 <= num <= den <= 2^32, so the quotient is at most 2^30; div_mod takes a divisor below
  // 2^32 without a 64-bit divide (a libgcc call on every Cortex-M), and den = 2^32 is a shift.
  const std::uint64_t scaled = static_cast<std::uint64_t>(num) << 30;
  if (den >> 32) return static_cast<std::int32_t>(scaled >> 32);
  return static_cast<std::int32_t>(fixedpoint::div_mod(scaled, static_cast<std::uint32_t>(den)).quotient);
}

// Written in place (out must be neither a nor b): a returned vertex would be one more
// temporary on the stack for each of the two cuts.
template <int P>
constexpr void lerp_vertex(const ClipVertex<P>& a, const ClipVertex<P>& b, std::int32_t t, int projector_begin,
                           int projector_end, ClipVertex<P>& out) {
  out.clip = lerp_wide(a.clip, b.clip, t);
  out.u = static_cast<std::int32_t>(lerp_wide(a.u, b.u, t));
  out.v = static_cast<std::int32_t>(lerp_wide(a.v, b.v, t));
  for (int j = projector_begin; j < projector_end; ++j) out.proj[j] = lerp_wide(a.proj[j], b.proj[j], t);
}

// Cuts the polygon by one plane, in place: edge i (vertex i to i + 1) gives
// vertex i when it is inside and the crossing when the edge crosses, in that
// order, as the two-buffer Sutherland-Hodgman does, with three vertices of
// scratch (the first vertex, and two slots taking turns for each edge's far end)
// instead of a second polygon (9 vertices of 40 + 32 P bytes: a frame's stack
// peak runs through here). Writes run ahead of reads by at most the
// number of exits (inside to outside) so far, so the input first moves up by
// exits - 1 slots: one exact convex polygon leaves a plane once and needs no
// move; a polygon that rounding has bent may leave it more often. False when
// nothing is left, or when the cut would pass the 3 + 6 vertices a triangle
// cut by six planes has (only a polygon rounding has bent can), so that no
// write ever leaves the array.
template <int P>
constexpr bool clip_against(ClipPolygon<P>& poly, ClipPlane plane, std::int64_t guard, int projector_begin,
                            int projector_end) {
  const int n = poly.count;
  std::int64_t d[max_clipped_vertices];
  bool any_out = false;
  for (int i = 0; i < n; ++i) {
    d[i] = plane_distance(plane, poly.v[i].clip, guard);
    any_out |= d[i] < 0;
  }
  if (!any_out) return true;
  int exits = 0, count = 0;
  for (int i = 0; i < n; ++i) {
    const bool in = d[i] >= 0, next_in = d[i + 1 == n ? 0 : i + 1] >= 0;
    count += (in ? 1 : 0) + (in != next_in ? 1 : 0);
    exits += in && !next_in ? 1 : 0;
  }
  const int shift = exits > 1 ? exits - 1 : 0;
  if (count < 3 || count > max_clipped_vertices || n + shift > max_clipped_vertices) return false;
  for (int i = n - 1; shift > 0 && i >= 0; --i) poly.v[i + shift] = poly.v[i];
  // Vertex k of the input is at poly.v[shift + k] until a write reaches it: the writes for edge i
  // land at or below i + exits <= shift + i + 1, whose vertex is already read (into `*b`).
  const ClipVertex<P> first = poly.v[shift];
  ClipVertex<P> scratch[2];
  const ClipVertex<P>* a = &first;
  int kept = 0;
  for (int i = 0; i < n; ++i) {
    const ClipVertex<P>* b = &first;
    if (i + 1 < n) {
      scratch[i & 1] = poly.v[shift + i + 1];
      b = &scratch[i & 1];
    }
    const std::int64_t da = d[i], db = d[i + 1 == n ? 0 : i + 1];
    if (da >= 0) poly.v[kept++] = *a;
    // Always cut from the inside vertex, so the same edge gives the same
    // point whichever triangle it belongs to (watertight across neighbours).
    if (da >= 0 && db < 0) lerp_vertex(*a, *b, crossing(da, db), projector_begin, projector_end, poly.v[kept++]);
    if (da < 0 && db >= 0) lerp_vertex(*b, *a, crossing(db, da), projector_begin, projector_end, poly.v[kept++]);
    a = b;
  }
  poly.count = kept;
  return true;
}

// Clips in place; returns false when nothing is left. Planes a triangle does
// not cross cost one distance check per vertex.
template <int P>
constexpr bool clip_polygon(ClipPolygon<P>& poly, std::int64_t guard, int projector_begin, int projector_end) {
  constexpr ClipPlane planes[] = {ClipPlane::near, ClipPlane::far, ClipPlane::left,
                                  ClipPlane::right, ClipPlane::bottom, ClipPlane::top};
  for (ClipPlane plane : planes)
    if (!clip_against(poly, plane, guard, projector_begin, projector_end)) return false;
  return true;
}

}  // namespace spanlight
