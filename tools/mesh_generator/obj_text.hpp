// An IndexedMesh as Wavefront OBJ text: `v x y z`, `vt u v`, `f p/t p/t p/t`
// (1-based), every number with 6 decimals.
#pragma once

#include <string>

#include "indexed_mesh.hpp"

namespace spanlight::mesh_generator {

// Decimals of every number the OBJ text holds: a printed value is within
// 0.5e-6 of the computed one.
inline constexpr int obj_decimals = 6;

// `comment` becomes the first lines, each prefixed with "# ".
std::string obj_text(const IndexedMesh& mesh, const std::string& comment);

}  // namespace spanlight::mesh_generator
