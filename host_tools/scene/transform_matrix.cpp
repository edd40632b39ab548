#include "transform_matrix.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace spanlight::scene::detail {

glm::dmat4 model_matrix(const TranslateRotateScale& parts) {
  // glm::translate/rotate/scale(m, ...) return m * X, so this builds T * Rz * Ry * Rx * S left to right.
  glm::dmat4 model = glm::translate(glm::dmat4(1.0), parts.translate);
  model = glm::rotate(model, glm::radians(parts.rotate_deg.z), glm::dvec3(0.0, 0.0, 1.0));
  model = glm::rotate(model, glm::radians(parts.rotate_deg.y), glm::dvec3(0.0, 1.0, 0.0));
  model = glm::rotate(model, glm::radians(parts.rotate_deg.x), glm::dvec3(1.0, 0.0, 0.0));
  return glm::scale(model, parts.scale);
}

}  // namespace spanlight::scene::detail
