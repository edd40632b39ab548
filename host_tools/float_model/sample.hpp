// Stage 5, sample: texel lookup with the scene's filters and wrap modes.
//
// Texture coordinate t = 0 is the BOTTOM row of the image as one looks at it,
// while images are stored top row first; rows here are counted from the bottom
// ("row_from_bottom") and turned around only where a texel is read.
//   nearest:  column floor(u * W), row_from_bottom floor(v * H)
//   bilinear: x = u * W - 0.5, y = v * H - 0.5 (texel centres at half-integers),
//             the four texels around (x, y) blended with weights (1-fx)(1-fy) ...
//   trilinear (v2): levels of scene/mip_chain.hpp; lambda = log2 rho, rho the longer of
//             the two screen-derivative vectors of (u * W, v * H); lambda <= 0: bilinear
//             at level 0; else d = min(lambda, last level), bilinear at floor(d) and
//             floor(d) + 1 (clamped to the last) mixed by d - floor(d).
// Projector images and falloff textures are never mipmapped: trilinear reads them
// bilinearly at level 0.
// Values are returned as doubles in [0, 1] (texel / 255), unrounded.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace spanlight::float_model {

// One texel, its indices first put through the wrap mode:
// repeat -> index mod size; clamp -> [0, size-1]; border -> black outside.
glm::dvec3 texel(const scene::Image& image, scene::Wrap wrap, long long column, long long row_from_bottom);

glm::dvec3 sample_nearest(const scene::Image& image, scene::Wrap wrap, glm::dvec2 uv);
glm::dvec3 sample_bilinear(const scene::Image& image, scene::Wrap wrap, glm::dvec2 uv);
// nearest or bilinear; trilinear is bilinear here (level 0).
glm::dvec3 sample(const scene::Image& image, scene::Filter filter, scene::Wrap wrap, glm::dvec2 uv);

// The level of detail lambda = log2(max(|d(U,V)/dx|, |d(U,V)/dy|)), (U, V) = (u * width, v * height).
// -infinity when both derivatives vanish.
double level_of_detail(glm::dvec2 duv_dx, glm::dvec2 duv_dy, int width, int height);

// `chain` from scene::mip_chain; lambda from level_of_detail.
glm::dvec3 sample_trilinear(const std::vector<scene::Image>& chain, scene::Wrap wrap, glm::dvec2 uv, double lambda);

// Per scene texture: its mip chain when it is trilinear, else empty.
using MipChains = std::vector<std::vector<scene::Image>>;
MipChains mip_chains(const scene::Scene& scene);

// An object's texture: its own filter and wrap (trilinear at level 0, as for lambda <= 0).
glm::dvec3 sample_texture(const scene::Texture& texture, glm::dvec2 uv);
// The same with its mip chain and level of detail, read only when the filter is trilinear.
glm::dvec3 sample_texture(const scene::Texture& texture, const std::vector<scene::Image>& chain, glm::dvec2 uv,
                          double lambda);

// A projector's falloff texture at (r/q, 0.5): its own filter, clamped to its edge.
glm::dvec3 sample_falloff(const scene::Texture& texture, double depth);

// A projector's image: its own filter, but always `border` (black outside the
// frustum, and bilinear blends toward black at the image edge).
glm::dvec3 sample_projector_image(const scene::Texture& texture, glm::dvec2 st);

}  // namespace spanlight::float_model
