// An animation (scene/animation.hpp) in the firmware's form: the SceneAnimation that
// `spanlight bake --animation` writes out and that `spanlight render --animation`
// plays through scene_pose_at_frame and build_frame_matrices, the calls the
// firmware makes, so both render each frame from the same matrices.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "prepare/prepare.hpp"
#include "scene/animation.hpp"
#include "spanlight/pose.hpp"
#include "spanlight/scene_animation.hpp"

namespace spanlight::prepare {

// Owns every array the SceneAnimation points into. Not copyable.
struct PreparedAnimation {
  SceneAnimation animation{};
  scene::Animation source;                // its tracks' key frames
  std::vector<AnimatedCamera> projectors;
  std::vector<Mat4Block> models;          // each object's model matrix, as mat4_block_from_doubles rounds it

  PreparedAnimation() = default;
  PreparedAnimation(const PreparedAnimation&) = delete;
  PreparedAnimation& operator=(const PreparedAnimation&) = delete;
};

// The frustums the animation does not move, in the firmware's formats: the camera's
// aspect is {width, height}; near, far and a projector's aspect are rounded to Q15.16.
CameraPose camera_lens(const scene::Scene& scene);
CameraPose projector_lens(const scene::Projector& projector);

std::unique_ptr<PreparedAnimation> prepare_animation(const scene::Scene& scene, const scene::Animation& animation);

// One frame's matrices on the host.
struct PosedMatrices {
  std::vector<Mat4Block> clip_from_object, projector_from_object, light_clip_from_object;

  explicit PosedMatrices(const PreparedScene& scene);
  MatrixStorage storage() { return {clip_from_object, projector_from_object, light_clip_from_object}; }
};

// Frame `frame`'s pose (scene_pose_at_frame) built into `out`.
PoseResult pose_frame(const PreparedScene& scene, const SceneAnimation& animation, std::uint32_t frame, PosedMatrices& out);

// What a failed pose means, for messages: "object "box" (objects[1]) seen by projector "spot" (projectors[0]): ...".
std::string describe_pose_failure(const PoseResult& result, const std::vector<std::string>& object_names,
                                  const scene::Scene& scene);

// Builds every frame's matrices; throws PrepareError with the whole message
// "ANIMATION: frames[K]: expected a pose the pipeline can build, got ..." for the first
// frame that fails, so a command refuses the animation before it writes anything.
void check_every_frame(const PreparedStorage& prepared, const PreparedAnimation& animation, const scene::Scene& scene);

}  // namespace spanlight::prepare
