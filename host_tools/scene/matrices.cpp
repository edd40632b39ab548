// The matrices the spec defines, in double with GLM's default conventions
// (right-handed, clip depth in [-w, w]). Both backends take them from here.
#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.hpp"

namespace spanlight::scene {

glm::dmat4 camera_view(const Camera& camera) { return glm::lookAt(camera.eye, camera.target, camera.up); }

glm::dmat4 camera_view_projection(const Scene& scene) {
  const Camera& camera = scene.camera;
  const double aspect = static_cast<double>(scene.width) / static_cast<double>(scene.height);
  return glm::perspective(glm::radians(camera.fovy_deg), aspect, camera.near, camera.far) * camera_view(camera);
}

glm::dmat4 projector_view(const Camera& camera, const Projector& projector) {
  const glm::dmat4 look = glm::lookAt(projector.eye, projector.target, projector.up);
  return projector.space == ProjectorSpace::camera ? look * camera_view(camera) : look;
}

glm::dmat4 projector_view_projection(const Camera& camera, const Projector& projector) {
  return glm::perspective(glm::radians(projector.fovy_deg), projector.aspect, projector.near, projector.far) *
         projector_view(camera, projector);
}

glm::dmat4 projector_texture_matrix(const Camera& camera, const Projector& projector) {
  // B maps clip coordinates in [-1, 1] to texture coordinates and depth in [0, 1].
  const glm::dmat4 bias = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)), glm::dvec3(0.5));
  return bias * projector_view_projection(camera, projector);
}

glm::dvec3 projector_eye_in_world(const Camera& camera, const Projector& projector) {
  if (projector.space == ProjectorSpace::world) return projector.eye;
  return glm::dvec3(glm::inverse(camera_view(camera)) * glm::dvec4(projector.eye, 1.0));
}

}  // namespace spanlight::scene
