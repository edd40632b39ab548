// The repeating textures of the generated models (power-of-two sizes, so the
// scenes can use `"wrap": "repeat"`; each one tiles without a visible edge).
#pragma once

#include "rgb_image.hpp"

namespace spanlight::mesh_generator {

RgbImage knit_texture();   // 256 x 256: stockinette stitches in coloured bands (the bear)
RgbImage tile_texture();   // 128 x 128: glazed tiles and grout (the torus knot)
RgbImage grass_texture();  // 128 x 128: grass and dry patches (the terrain)

}  // namespace spanlight::mesh_generator
