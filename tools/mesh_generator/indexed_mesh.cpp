#include "indexed_mesh.hpp"

namespace spanlight::mesh_generator {

void append(IndexedMesh& mesh, const IndexedMesh& part) {
  const auto position_offset = static_cast<std::uint32_t>(mesh.positions.size());
  const auto uv_offset = static_cast<std::uint32_t>(mesh.uvs.size());
  mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
  mesh.uvs.insert(mesh.uvs.end(), part.uvs.begin(), part.uvs.end());
  for (Face face : part.faces) {
    for (Corner& corner : face) {
      corner.position += position_offset;
      corner.uv += uv_offset;
    }
    mesh.faces.push_back(face);
  }
}

}  // namespace spanlight::mesh_generator
