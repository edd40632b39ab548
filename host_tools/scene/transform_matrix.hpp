// The model matrix of a {translate, rotate_deg, scale} transform.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace spanlight::scene::detail {

struct TranslateRotateScale {
  glm::dvec3 translate{0.0};
  glm::dvec3 rotate_deg{0.0};  // degrees about the world x, y, z axes
  glm::dvec3 scale{1.0};
};

// M = T * Rz * Ry * Rx * S: scale first, then rotate about x, y, z, then translate.
glm::dmat4 model_matrix(const TranslateRotateScale& parts);

}  // namespace spanlight::scene::detail
