// A mesh as an exported model stores it: positions and texture coordinates in
// two lists, each triangle corner naming one of each (OBJ's "f v/vt"). A
// position is shared by every triangle around it; a uv seam is a position with
// two or more uvs.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace spanlight::mesh_generator {

struct Corner {
  std::uint32_t position;  // index into IndexedMesh::positions
  std::uint32_t uv;        // index into IndexedMesh::uvs
};

// Corners counter-clockwise seen from the front (outside of a closed surface).
using Face = std::array<Corner, 3>;

struct IndexedMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec2> uvs;
  std::vector<Face> faces;
};

// Adds `part` to `mesh`, its indices moved past the ones `mesh` has.
void append(IndexedMesh& mesh, const IndexedMesh& part);

}  // namespace spanlight::mesh_generator
