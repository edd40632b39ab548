// The eye's depth pass: the nearest surface of every pixel (depth test `less`
// against a buffer cleared to 1, objects and triangles in file order) and what
// is interpolated there. render.cpp shades from it; the sweep reads its texture
// coordinates as the exact values the fixed pipeline is measured against.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace spanlight::float_model {

// Per pixel, the nearest surface and its interpolated attributes (one (s, t, r, q)
// per projector), its texture's level of detail, and which projectors its
// triangle faces (facing.hpp).
struct VisibleSurfaces {
  std::size_t projectors = 0;
  std::vector<double> depth;           // window depth; 1 where nothing was drawn
  std::vector<int> object;             // -1 on background
  std::vector<std::int64_t> triangle;  // scene-wide triangle number (objects in file order); -1 on background
  std::vector<glm::dvec2> uv;
  std::vector<double> lambda;          // trilinear textures only; -infinity elsewhere
  std::vector<glm::dvec4> strq;        // pixel-major, `projectors` entries per pixel
  std::vector<std::uint8_t> facing;    // pixel-major like strq
};

VisibleSurfaces resolve_visibility(const scene::Scene& scene);

}  // namespace spanlight::float_model
