#include "float_model/facing.hpp"

namespace spanlight::float_model {

bool strictly_same_side(const std::array<glm::dvec3, 3>& triangle, glm::dvec3 a, glm::dvec3 b) {
  const glm::dvec3 normal = glm::cross(triangle[1] - triangle[0], triangle[2] - triangle[0]);
  const double side_a = glm::dot(normal, a - triangle[0]);
  const double side_b = glm::dot(normal, b - triangle[0]);
  return (side_a > 0.0 && side_b > 0.0) || (side_a < 0.0 && side_b < 0.0);  // a zero normal gives 0: never
}

std::vector<std::uint8_t> projectors_facing(const scene::Scene& scene, const scene::Object& object, std::size_t index) {
  std::vector<std::uint8_t> facing(scene.projectors.size(), 1);
  std::array<glm::dvec3, 3> world{};
  bool transformed = false;
  for (std::size_t j = 0; j < scene.projectors.size(); ++j) {
    const scene::Projector& projector = scene.projectors[j];
    if (!projector.facing_only) continue;
    if (!transformed) {
      for (std::size_t corner = 0; corner < 3; ++corner) {
        const glm::dvec3& position = object.mesh.positions[object.mesh.triangles[index][corner]];
        world[corner] = glm::dvec3(object.model * glm::dvec4(position, 1.0));
      }
      transformed = true;
    }
    facing[j] = strictly_same_side(world, scene.camera.eye, scene::projector_eye_in_world(scene.camera, projector)) ? 1 : 0;
  }
  return facing;
}

}  // namespace spanlight::float_model
