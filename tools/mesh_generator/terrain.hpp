// A terrain patch: a height field over a 3 x 2 unit grid of 48 x 32 cells
// (3072 triangles), a hill rising to about 0.6 with ridges on its flanks. An
// open mesh: its border edges belong to one triangle each. Faces point up (+y).
#pragma once

#include "indexed_mesh.hpp"

namespace spanlight::mesh_generator {

IndexedMesh terrain();  // uvs for the grass texture (textures.hpp), 4 repeats across

}  // namespace spanlight::mesh_generator
