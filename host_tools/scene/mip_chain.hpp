// The mipmap chain of a trilinear texture (docs/scene-format.md, "Mipmapped
// textures"): level 0 is the image; level k+1 halves each side larger than 1, each
// texel the mean of the 2x2 (2x1, 1x2) texels of level k it covers, per channel in
// 8-bit values rounded half up; the last level is 1x1. Both backends build their
// levels here, so they mix the same bytes.
//
// Size: a 2^a x 2^b chain has max(a, b) + 1 levels. For a square image the chain
// holds (4^(a+1) - 1) / 3 < 4/3 of the image's texels (the spec's bound); a long
// thin image holds more: 2^a x 1 gives 2 * 2^a - 1 texels, just under twice.
#pragma once

#include <cstddef>
#include <vector>

#include "scene/scene.hpp"

namespace spanlight::scene {

// Levels 0 (a copy of `image`) .. last (1x1). Throws std::invalid_argument when a
// side is not a power of two (the loader refuses trilinear on such an image).
std::vector<Image> mip_chain(const Image& image);

// The next level of `level` (which must not be 1x1), as defined above.
Image half_level(const Image& level);

// Texels in the whole chain of a width x height power-of-two image.
std::size_t mip_chain_texels(int width, int height);

}  // namespace spanlight::scene
