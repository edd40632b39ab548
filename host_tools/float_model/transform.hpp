// Stage 1, transform: object space to the eye's clip space, and every
// projector's projective texture coordinates (s, t, r, q) = B * P_j * V_j * M * v.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace spanlight::float_model {

// One vertex as the clipper sees it: a clip-space position and the attributes
// that are interpolated with it (all of them linearly in clip space).
struct ClipVertex {
  glm::dvec4 position{0.0};             // clip = VP * M * v
  glm::dvec2 uv{0.0};                   // the object's texture coordinates
  std::vector<glm::dvec4> projector;    // (s, t, r, q) per projector, in scene order
};

using ClipTriangle = std::array<ClipVertex, 3>;

// The matrices one object needs: where its vertices land in clip space, and
// where they land in each projector's texture space.
struct ObjectTransform {
  glm::dmat4 clip_from_object{1.0};
  std::vector<glm::dmat4> projector_from_object;  // empty for depth-only passes
};

// The eye pass: clip = camera_view_projection * M, and B * P_j * V_j * M per projector.
ObjectTransform eye_transform(const scene::Scene& scene, const scene::Object& object);

// A depth-only pass from a projector: clip = P_j * V_j * M, no attributes.
ObjectTransform projector_depth_transform(const scene::Projector& projector, const scene::Object& object);

// The three vertices of mesh triangle `index`, transformed.
ClipTriangle transform_triangle(const ObjectTransform& transform, const scene::Mesh& mesh, std::size_t index);

}  // namespace spanlight::float_model
