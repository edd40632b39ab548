// Reads a Wavefront OBJ file (v, optional vt, polygon faces) into a Mesh.
#pragma once

#include <filesystem>
#include <string>

#include "scene/scene.hpp"

namespace spanlight::scene::detail {

// Polygons are fan-triangulated in file order: (0,1,2), (0,2,3), ...
// A Mesh vertex is one distinct (v, vt) pair of the faces, in order of first use;
// corners without vt get uv 0. Errors name obj_file and field_path, the scene
// field that named it.
Mesh load_obj_mesh(const std::filesystem::path& obj_file, const std::string& field_path);

}  // namespace spanlight::scene::detail
