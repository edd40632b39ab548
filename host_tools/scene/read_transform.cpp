// objects[].transform: {translate, rotate_deg, scale} or {matrix}.
#include "scene_readers.hpp"
#include "transform_matrix.hpp"

namespace spanlight::scene::detail {
namespace {

glm::dmat4 read_column_major_matrix(const JsonField& matrix) {
  const auto numbers = matrix.elements(16, "16 numbers (a 4x4 matrix, column-major)");
  glm::dmat4 model(1.0);
  for (glm::length_t column = 0; column < 4; ++column) {
    for (glm::length_t row = 0; row < 4; ++row) {
      model[column][row] = numbers[static_cast<std::size_t>(column * 4 + row)].number();
    }
  }
  return model;
}

}  // namespace

glm::dmat4 read_transform(const JsonField& transform) {
  transform.expect_object_with_fields({"translate", "rotate_deg", "scale", "matrix"});
  if (transform.has("matrix")) {
    for (const std::string_view part : {"translate", "rotate_deg", "scale"}) {
      if (transform.has(part)) {
        transform.fail_member(part, "expected either matrix or translate/rotate_deg/scale, got both matrix and " +
                                        std::string(part));
      }
    }
    return read_column_major_matrix(transform.required("matrix"));
  }
  TranslateRotateScale parts;
  if (const auto translate = transform.optional("translate")) parts.translate = translate->vec3();
  if (const auto rotate = transform.optional("rotate_deg")) parts.rotate_deg = rotate->vec3();
  if (const auto scale = transform.optional("scale")) parts.scale = scale->vec3();
  return model_matrix(parts);
}

}  // namespace spanlight::scene::detail
