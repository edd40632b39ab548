// Stage 6, shade: what a visible pixel shows (spec, "What a pixel shows").
//
//   light   = min(1, ambient + sum_j lit_j * shadow_j * color_j * image_j(s/q, t/q) * falloff_j(r/q))
//   surface = object.color * texture(u, v)        (no texture: 1; trilinear at the pixel's lambda)
//   pixel   = light * surface                     (background: 0)
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "float_model/sample.hpp"
#include "float_model/shadow_map.hpp"
#include "scene/scene.hpp"

namespace spanlight::float_model {

// (s/q, t/q, r/q) when the point is lit by the projector's frustum: q > 0, and
// s/q, t/q, r/q each in [0, 1] (conditions 1-3 of the spec). nullopt otherwise.
std::optional<glm::dvec3> project_into_frustum(glm::dvec4 strq);

// Projector j's contribution at a point with interpolated (s, t, r, q):
// lit * shadow * color * image(s/q, t/q) * falloff(r/q). `shadow_map` is null without
// shadows; `facing` is false when facing_only keeps the light off the triangle (facing.hpp).
glm::dvec3 projector_light(const scene::Scene& scene, const scene::Projector& projector, const ShadowMap* shadow_map,
                           glm::dvec4 strq, bool facing = true);

// The light at a pixel: ambient plus every projector, clamped to 1 per channel.
// `strq` holds one (s, t, r, q) per projector, `shadow_maps` one entry per
// projector (empty maps for projectors without shadows), `facing` one flag per
// projector (empty: every projector faces the surface).
glm::dvec3 pixel_light(const scene::Scene& scene, const std::vector<ShadowMap>& shadow_maps,
                       const std::vector<glm::dvec4>& strq, const std::vector<std::uint8_t>& facing = {});

// The surface colour: object colour times its texture at uv. A trilinear texture reads
// its chain in `chains` (mip_chains) at level of detail `lambda`.
glm::dvec3 surface_color(const scene::Scene& scene, const scene::Object& object, glm::dvec2 uv,
                         const MipChains& chains = {}, double lambda = 0.0);

// round(255 * value), clamped to 0..255.
std::uint8_t to_byte(double value);

}  // namespace spanlight::float_model
