// Stage 5, sample: texel lookup with the scene's filters and wrap modes.
//
// Texture coordinate t = 0 is the BOTTOM row of the image as one looks at it,
// while images are stored top row first; rows here are counted from the bottom
// ("row_from_bottom") and turned around only where a texel is read.
//   nearest:  column floor(u * W), row_from_bottom floor(v * H)
//   bilinear: x = u * W - 0.5, y = v * H - 0.5 (texel centres at half-integers),
//             the four texels around (x, y) blended with weights (1-fx)(1-fy) ...
// Values are returned as doubles in [0, 1] (texel / 255), unrounded.
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace spanlight::float_model {

// One texel, its indices first put through the wrap mode:
// repeat -> index mod size; clamp -> [0, size-1]; border -> black outside.
glm::dvec3 texel(const scene::Image& image, scene::Wrap wrap, long long column, long long row_from_bottom);

glm::dvec3 sample_nearest(const scene::Image& image, scene::Wrap wrap, glm::dvec2 uv);
glm::dvec3 sample_bilinear(const scene::Image& image, scene::Wrap wrap, glm::dvec2 uv);
glm::dvec3 sample(const scene::Image& image, scene::Filter filter, scene::Wrap wrap, glm::dvec2 uv);

// An object's texture: its own filter and wrap.
glm::dvec3 sample_texture(const scene::Texture& texture, glm::dvec2 uv);

// A projector's image: its own filter, but always `border` (black outside the
// frustum, and bilinear blends toward black at the image edge).
glm::dvec3 sample_projector_image(const scene::Texture& texture, glm::dvec2 st);

}  // namespace spanlight::float_model
