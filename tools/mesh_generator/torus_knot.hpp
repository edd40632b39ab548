// A (2, 3) torus knot (a trefoil) as a closed tube around the z axis, about
// 3 units across: one long, twisting surface that hides parts of itself.
#pragma once

#include "indexed_mesh.hpp"

namespace spanlight::mesh_generator {

IndexedMesh torus_knot();  // uvs for the tile texture (tile_texture.hpp)

}  // namespace spanlight::mesh_generator
