// A knitted teddy bear sitting on the ground (y = 0), facing +z, about 1.25
// units tall: body, head, snout, ears, arms and legs, each a closed body part
// (body_part.hpp) pushed into its neighbours, as many game characters are
// built. The eyes and the nose are a second mesh, drawn in their own colour.
#pragma once

#include "indexed_mesh.hpp"

namespace spanlight::mesh_generator {

IndexedMesh bear_body();     // uvs for the knit texture (knit_texture.hpp)
IndexedMesh bear_buttons();  // button eyes and nose

}  // namespace spanlight::mesh_generator
