// Shadow maps (Segal et al., section 4): a depth-only render of every object from
// a projector, then the per-pixel comparison r/q - bias <= D.
//
// The map is rendered exactly like the eye's depth: clip = P_j * V_j * M * v,
// near/far clipping, snapping, the same coverage rule, each object's own cull
// setting, depth test `less`, cleared to 1. Row 0 of the map is at the top, the
// t = 1 side; lookups count rows from the bottom like every texture.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace spanlight::float_model {

struct ShadowMap {
  int size = 0;
  std::vector<double> depth;  // size * size window depths, top row first

  // Indices are clamped to the map.
  double at(long long column, long long row_from_bottom) const;
};

ShadowMap render_shadow_map(const scene::Scene& scene, const scene::Projector& projector);

// The fraction of light that reaches a point with projector coordinates
// (s/q, t/q, r/q): 1 lit, 0 shadowed; pcf2x2 gives the bilinear blend of four
// comparisons (texel centres at half-integers, indices clamped to the map).
double shadow_factor(const ShadowMap& map, const scene::Shadows& shadows, glm::dvec3 projected);

}  // namespace spanlight::float_model
