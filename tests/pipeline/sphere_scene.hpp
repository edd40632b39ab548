// A closed UV sphere for the draw-order and closed-solid tests (5_frame/draw.hpp,
// 1_vertex/closed.hpp), in a scene of its own: radius 1 at the origin, textured
// with repeating stripes, the camera outside it.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>

#include "pipeline_support.hpp"

namespace spanlight::ptest {

// A closed UV sphere of radius 1 at the origin, counter-clockwise seen from outside, its
// triangles ring by ring and around each ring, so front and back faces alternate in the
// file. uv wraps once around and once pole to pole (a repeating texture).
inline scene::Object sphere(int rings, int segments, scene::Cull cull) {
  scene::Object object;
  object.name = "sphere";
  object.cull = cull;
  object.texture = 0;
  for (int r = 0; r <= rings; ++r) {
    const double polar = std::numbers::pi * r / rings;
    for (int s = 0; s <= segments; ++s) {  // the seam's column twice, with u = 0 and u = 1
      const double around = 2.0 * std::numbers::pi * s / segments;
      object.mesh.positions.emplace_back(std::sin(polar) * std::cos(around), std::cos(polar), -std::sin(polar) * std::sin(around));
      object.mesh.uvs.emplace_back(static_cast<double>(s) / segments, 1.0 - static_cast<double>(r) / rings);
    }
  }
  const auto at = [segments](int r, int s) { return static_cast<std::uint32_t>(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      // Seen from outside, with y up and the ring running towards -z from +x: (r, s), (r + 1, s),
      // (r + 1, s + 1) is counter-clockwise. The poles' degenerate halves are left out.
      if (r + 1 < rings) object.mesh.triangles.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
      if (r > 0) object.mesh.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
    }
  return object;
}

inline scene::Scene sphere_scene(scene::Cull cull) {
  auto s = empty_scene(160, 120, {0.3, 0.5, 3.5}, {0, 0, 0}, {0, 1, 0}, 45.0, 0.5, 10.0);
  s.ambient = glm::dvec3(1.0);
  scene::Image stripes = solid_image(16, 16, {40, 90, 200});
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; x += 2)
      for (int c = 0; c < 3; ++c) stripes.rgb[static_cast<std::size_t>((y * 16 + x) * 3 + c)] = 230;
  s.textures.push_back(texture("stripes", stripes, scene::Filter::bilinear, scene::Wrap::repeat));
  s.objects.push_back(sphere(16, 32, cull));
  return s;
}


}  // namespace spanlight::ptest
