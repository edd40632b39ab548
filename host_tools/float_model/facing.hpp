// facing_only (scene format 2): a triangle is lit by such a projector only when the
// projector's eye and the camera's eye lie strictly on the same side of the
// triangle's plane (its three vertices after M). A triangle of zero area has no
// plane and is never lit; an eye in the plane is on neither side.
//
// The sides are the signs of n . (eye - p0) with n = (p1 - p0) x (p2 - p0), in
// double: exact when the coordinates and their products are (the hand-made tests
// put walls and eyes on small integers); otherwise an eye within rounding of the
// plane may fall on either side.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace spanlight::float_model {

bool strictly_same_side(const std::array<glm::dvec3, 3>& triangle, glm::dvec3 a, glm::dvec3 b);

// For mesh triangle `index` of `object`: 1 per projector that may light it (always 1
// without facing_only), in scene order.
std::vector<std::uint8_t> projectors_facing(const scene::Scene& scene, const scene::Object& object, std::size_t index);

}  // namespace spanlight::float_model
