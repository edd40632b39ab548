// Stage 1d, each vertex once: an object's vertices are transformed, tested
// against the clip planes and (when inside all of them) divided and snapped
// once per pass, into a caller-owned buffer (FrameTarget::vertices), so a
// vertex shared by six triangles costs one transform, not six. Triangles with
// a vertex outside a plane go through the clip stage from their positions
// again; clip_polygon keeps inside vertices as they are, so both ways give the
// same window position for a vertex.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <utility>

#include "spanlight/1_vertex/clip.hpp"
#include "spanlight/1_vertex/project.hpp"
#include "spanlight/1_vertex/transform.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

struct CachedVertex {
  ScreenVertex screen;  // valid when `outside` is 0
  std::uint8_t outside;  // bit k: beyond clip plane k (ClipPlane order)
};

inline constexpr ClipPlane clip_planes[] = {ClipPlane::near, ClipPlane::far, ClipPlane::left,
                                           ClipPlane::right, ClipPlane::bottom, ClipPlane::top};

// Bit k set where point c lies more than `margin` beyond plane k. Unrolled over the planes, so
// each distance is its formula alone (looped, -Os dispatched each through a switch table).
template <std::size_t... K>
constexpr unsigned planes_beyond(const Vec4Wide& c, std::int64_t gw, std::int64_t margin, std::index_sequence<K...>) {
  return ((plane_distance_with(clip_planes[K], c, gw) < -margin ? 1u << K : 0u) | ...);
}
constexpr unsigned planes_beyond(const Vec4Wide& c, std::int64_t guard, std::int64_t margin) {
  return planes_beyond(c, guard_w(c, guard), margin, std::make_index_sequence<std::size(clip_planes)>{});
}

constexpr std::uint8_t outside_planes(const Vec4Wide& c, std::int64_t guard) {
  return static_cast<std::uint8_t>(planes_beyond(c, guard, 0));
}

// Corner k (bits 0, 1, 2: max x, y, z) of an object's bounding box, in clip space. Every point of
// the box is a convex combination of its corners; the computed distance of a point to a clip plane
// differs from the linear one by under guard + 2 units (clip coordinates rounded to Q.32, the guard
// planes' quarter-unit floors), so a bound that holds at every corner by more than
// box_corner_margin holds at every vertex.
constexpr Vec4Wide clip_box_corner(const Bounds& box, const Mat4Block& to_clip, unsigned corner) {
  const std::int32_t p[3] = {(corner & 1u) ? box.max[0] : box.min[0], (corner & 2u) ? box.max[1] : box.min[1],
                             (corner & 4u) ? box.max[2] : box.min[2]};
  return transform(to_clip, p);
}
constexpr std::int64_t box_corner_margin(std::int64_t guard) { return 2 * (guard + 2); }

// Whether a whole object lies beyond one clip plane, from its bounding box: then every vertex
// is beyond that plane, so no triangle of it can show and none need be transformed. Eight
// transforms: worth it for objects of more vertices than that. Out of line: it runs once an
// object, and inlined (GCC does on Cortex-M4) its 200 bytes of corners sat in draw_pass's frame
// under every triangle's walk.
[[gnu::noinline]] constexpr bool object_beyond_a_plane(const Bounds& box, const Mat4Block& to_clip, std::int64_t guard) {
  unsigned beyond_all = 0x3Fu;
  for (unsigned corner = 0; corner < 8 && beyond_all != 0; ++corner)
    beyond_all &= planes_beyond(clip_box_corner(box, to_clip, corner), guard, box_corner_margin(guard));
  return beyond_all != 0;
}

// Whether every vertex of the object lies in front of the near plane: every corner of its
// bounding box is by more than box_corner_margin (1_vertex/closed.hpp).
constexpr bool object_before_near(const Bounds& box, const Mat4Block& to_clip, std::int64_t guard) {
  for (unsigned corner = 0; corner < 8; ++corner)
    if (plane_distance_with(ClipPlane::near, clip_box_corner(box, to_clip, corner), 0) <= box_corner_margin(guard)) return false;
  return true;
}

inline void cache_vertices(const ObjectData& object, const Mat4Block& to_clip, int width, int height, std::int64_t guard,
                           CachedVertex* out) {
  for (std::uint32_t i = 0; i < object.vertex_count; ++i) {
    const Vec4Wide c = transform(to_clip, object.positions + i * 3);
    CachedVertex& v = out[i];
    v.outside = outside_planes(c, guard);
    if (v.outside == 0) v.screen = project(c, width, height);
  }
}

}  // namespace spanlight
