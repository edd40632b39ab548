// Lets Catch print GLM vectors in failure messages instead of "{?}".
#pragma once

#include <sstream>

#include <catch2/catch.hpp>
#include <glm/glm.hpp>

namespace Catch {

template <glm::length_t N, typename T, glm::qualifier Q>
struct StringMaker<glm::vec<N, T, Q>> {
  static std::string convert(const glm::vec<N, T, Q>& value) {
    std::ostringstream text;
    text.precision(17);
    text << "(";
    for (glm::length_t i = 0; i < N; ++i) text << (i ? ", " : "") << value[i];
    text << ")";
    return text.str();
  }
};

}  // namespace Catch
