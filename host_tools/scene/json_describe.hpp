// The "got ..." half of an error message: a short description of what the
// file actually holds, and numbers printed the shortest way that reads back.
#pragma once

#include <string>

#include <glm/vec3.hpp>

#include "json_document.hpp"

namespace spanlight::scene::detail {

std::string describe(const Json& value);  // 190, "mirror", an array of 2 elements, an object, null
std::string format_number(double value);  // shortest round-trip form: 0.1, 190, 1e+23
std::string format_vec3(const glm::dvec3& value);  // [0, 1, 0]

}  // namespace spanlight::scene::detail
