// Seeded random inputs for the pose builders, inside their supported ranges
// (pose_status.hpp, perspective.hpp), and the matrix chains the firmware builds
// from them, each with its GLM reference and bound. Shared by
// test_pose_builders.cpp and the spanlight_pose_accuracy tool.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "fixedpoint/look_at.hpp"
#include "fixedpoint/mat4.hpp"
#include "fixedpoint/perspective.hpp"
#include "pose_reference.hpp"

namespace random_poses {

struct Pose {
  fixedpoint::Vec3Q16 eye, target, up;
  fixedpoint::Turns fovy;
  fixedpoint::Aspect aspect;
  fixedpoint::q16 near, far;
  fixedpoint::Mat4Block model;
};

inline double uniform(std::mt19937_64& rng, double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(rng);
}

inline double log_uniform(std::mt19937_64& rng, double low, double high) {
  return std::exp2(uniform(rng, std::log2(low), std::log2(high)));
}

inline fixedpoint::Vec3Q16 point(std::mt19937_64& rng, double extent) {
  return fixedpoint::vec3_q16(uniform(rng, -extent, extent), uniform(rng, -extent, extent), uniform(rng, -extent, extent));
}

inline glm::dvec3 direction(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  return glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
}

// fovy mostly in [1, 179] degrees, a quarter of the time within a factor 2^10 of either end of its range.
inline fixedpoint::Turns fovy(std::mt19937_64& rng) {
  const double min_degrees = fixedpoint::degrees(fixedpoint::Turns{fixedpoint::min_fovy_raw});
  switch (rng() % 8) {
    case 0: return fixedpoint::turns_from_degrees(log_uniform(rng, min_degrees, min_degrees * 1024));
    case 1: return fixedpoint::turns_from_degrees(180.0 - log_uniform(rng, min_degrees, min_degrees * 1024));
    default: return fixedpoint::turns_from_degrees(uniform(rng, 1.0, 179.0));
  }
}

// A model matrix T * R * S (random axis and angle, scales in [1/4, 4]), translation within extent.
inline fixedpoint::Mat4Block model(std::mt19937_64& rng, double extent) {
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(uniform(rng, -extent, extent), uniform(rng, -extent, extent),
                                                            uniform(rng, -extent, extent)));
  m = glm::rotate(m, uniform(rng, -3.2, 3.2), direction(rng));
  m = glm::scale(m, glm::dvec3(log_uniform(rng, 0.25, 4), log_uniform(rng, 0.25, 4), log_uniform(rng, 0.25, 4)));
  double col_major[16];
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) col_major[c * 4 + r] = m[c][r];
  return fixedpoint::mat4_block_from_doubles(col_major);
}

// The kinds of poses drawn: a camera in a room as the demo has it, and anything the ranges allow
// at two scales (eye, target and the model's translation within +-extent).
struct Regime {
  const char* name;
  double extent;
  bool room_camera;  // aspect 4:3, fovy in [30, 90], near in [0.05, 1], far in [20, 200]
  std::uint64_t seed;
};

inline constexpr Regime regimes[] = {
    {"room", 16.0, true, 20240613},
    {"any", 64.0, false, 20240614},
    {"wide", 8000.0, false, 20240615},
};

// eye and target within +-extent (distinct), up of length in [1/16, 16] and away from the view
// direction; otherwise fovy (above), aspect w/h with w, h in [1, 4096], near in [2^-8, 16],
// far up to 4096 times near and below 2^14.
inline Pose pose(std::mt19937_64& rng, const Regime& regime) {
  Pose p{};
  do {
    p.eye = point(rng, regime.extent);
    p.target = point(rng, regime.extent);
    const glm::dvec3 up = direction(rng) * log_uniform(rng, 1.0 / 16, 16);
    p.up = fixedpoint::vec3_q16(up.x, up.y, up.z);
  } while (fixedpoint::look_at(p.eye, p.target, p.up).status != fixedpoint::PoseStatus::ok);
  if (regime.room_camera) {
    p.fovy = fixedpoint::turns_from_degrees(uniform(rng, 30.0, 90.0));
    p.aspect = {320, 240};
    p.near = fixedpoint::q16::from_double(log_uniform(rng, 0.05, 1.0));
    p.far = fixedpoint::q16::from_double(log_uniform(rng, 20.0, 200.0));
  } else {
    p.fovy = fovy(rng);
    p.aspect = {static_cast<std::uint32_t>(1 + rng() % 4096), static_cast<std::uint32_t>(1 + rng() % 4096)};
    const double near = log_uniform(rng, 1.0 / 256, 16);
    p.near = fixedpoint::q16::from_double(near);
    p.far = fixedpoint::q16::from_double(std::fmin(near * log_uniform(rng, 1.01, 4096), 16000.0));
  }
  p.model = model(rng, regime.extent);
  return p;
}

// The matrices built from one pose and what each should be.
struct Built {
  fixedpoint::Mat4 view, projection, view_from_object, clip_from_object, texture_from_object;
  fixedpoint::BlockResult clip_block, texture_block;  // what the pipeline gets
  fixedpoint::Mat4 clip_left_to_right;                // (P * mat4(V)) * M, the order look_at.hpp advises against
  pose_reference::Expected view_expected, projection_expected, view_from_object_expected, clip_expected, texture_expected,
      clip_block_expected, texture_block_expected, clip_left_to_right_expected;
};

// As the firmware builds them: clip_from_object = P * (V * M), texture_from_object = B * clip_from_object
// (a projector's B * P_j * (V_j * M)), each turned into the pipeline's block; and GLM's lookAt matrix, mat4(V).
inline Built build(const Pose& p) {
  using namespace fixedpoint;
  using namespace pose_reference;
  Built b{};
  const View view = look_at(p.eye, p.target, p.up);
  b.view = mat4(view);
  b.projection = perspective(p.fovy, p.aspect, p.near, p.far);
  b.view_from_object = view * mat4(p.model);
  b.clip_from_object = b.projection * b.view_from_object;
  b.texture_from_object = bias() * b.clip_from_object;
  b.clip_block = pipeline_matrix(b.clip_from_object);
  b.texture_block = pipeline_matrix(b.texture_from_object);

  b.view_expected = expected_look_at(p.eye, p.target, p.up, b.view);
  b.projection_expected = expected_perspective(p.fovy, p.aspect, p.near, p.far, b.projection);
  b.view_from_object_expected = expected_view_times(p.eye, p.target, p.up, exact(p.model), b.view_from_object);
  b.clip_expected = expected_product(b.projection_expected, b.view_from_object_expected, b.projection, b.view_from_object,
                                     b.clip_from_object);
  b.texture_expected = expected_product(expected_bias(), b.clip_expected, bias(), b.clip_from_object, b.texture_from_object);
  b.clip_block_expected = expected_block(b.clip_expected, b.clip_block.block);
  b.texture_block_expected = expected_block(b.texture_expected, b.texture_block.block);

  const Mat4 projection_view = b.projection * b.view;
  b.clip_left_to_right = projection_view * mat4(p.model);
  const Expected pv = expected_product(b.projection_expected, b.view_expected, b.projection, b.view, projection_view);
  b.clip_left_to_right_expected = expected_product(pv, exact(p.model), projection_view, mat4(p.model), b.clip_left_to_right);
  return b;
}

}  // namespace random_poses
