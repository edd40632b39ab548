// An object's inline geometry: positions, optional uvs, triangles.
#include "scene_readers.hpp"

namespace spanlight::scene::detail {

Mesh read_inline_mesh(const JsonField& object) {
  Mesh mesh;
  for (const JsonField& position : object.required("positions").elements()) mesh.positions.push_back(position.vec3());
  const std::size_t count = mesh.positions.size();

  if (const auto uvs = object.optional("uvs")) {
    const std::string per_position = std::to_string(count) + " [u, v] pairs, one per position";
    for (const JsonField& uv : uvs->elements(count, per_position)) mesh.uvs.push_back(uv.vec2());
  } else {
    mesh.uvs.assign(count, glm::dvec2(0.0));  // spec: missing uvs mean uv 0
  }

  const auto last_index = static_cast<std::int64_t>(count) - 1;
  const std::string meaning = "an index into positions, which has " + std::to_string(count) + " entries";
  for (const JsonField& triangle : object.required("triangles").elements()) {
    const auto corners = triangle.elements(3, "3 indices [i, j, k]");
    std::array<std::uint32_t, 3> indices{};
    for (std::size_t i = 0; i < 3; ++i) indices[i] = static_cast<std::uint32_t>(corners[i].integer(0, last_index, meaning));
    mesh.triangles.push_back(indices);
  }
  return mesh;
}

}  // namespace spanlight::scene::detail
