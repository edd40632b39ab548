// Stage 1d, each vertex once: an object's vertices are transformed, tested
// against the clip planes and (when inside all of them) divided and snapped
// once per pass, into a caller-owned buffer (FrameTarget::vertices), so a
// vertex shared by six triangles costs one transform, not six. Triangles with
// a vertex outside a plane go through the clip stage from their positions
// again; clip_polygon keeps inside vertices as they are, so both ways give the
// same window position for a vertex.
#pragma once

#include <cstdint>

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

constexpr std::uint8_t outside_planes(const Vec4Wide& c, std::int64_t guard) {
  std::uint8_t bits = 0;
  for (int k = 0; k < 6; ++k) bits = static_cast<std::uint8_t>(bits | (plane_distance(clip_planes[k], c, guard) < 0 ? 1u << k : 0u));
  return bits;
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
