#include "float_model/transform.hpp"

namespace spanlight::float_model {

ObjectTransform eye_transform(const scene::Scene& scene, const scene::Object& object) {
  ObjectTransform transform;
  transform.clip_from_object = scene::camera_view_projection(scene) * object.model;
  for (const scene::Projector& projector : scene.projectors) {
    transform.projector_from_object.push_back(scene::projector_texture_matrix(scene.camera, projector) * object.model);
  }
  transform.uvs = scene::vertex_uvs(scene.camera, object);
  return transform;
}

ObjectTransform projector_depth_transform(const scene::Camera& camera, const scene::Projector& projector,
                                          const scene::Object& object) {
  ObjectTransform transform;
  transform.clip_from_object = scene::projector_view_projection(camera, projector) * object.model;
  return transform;
}

ClipTriangle transform_triangle(const ObjectTransform& transform, const scene::Mesh& mesh, std::size_t index) {
  ClipTriangle triangle;
  for (std::size_t corner = 0; corner < 3; ++corner) {
    const std::uint32_t vertex = mesh.triangles[index][corner];
    const glm::dvec4 object_position(mesh.positions[vertex], 1.0);
    ClipVertex& out = triangle[corner];
    out.position = transform.clip_from_object * object_position;
    out.uv = vertex < transform.uvs.size() ? transform.uvs[vertex] : glm::dvec2(0.0);
    for (const glm::dmat4& projector_from_object : transform.projector_from_object) {
      out.projector.push_back(projector_from_object * object_position);
    }
  }
  return triangle;
}

}  // namespace spanlight::float_model
