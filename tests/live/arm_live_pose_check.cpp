// The run-time pose API as firmware calls it (pose.hpp, scene_animation.hpp), compiled for
// Cortex-M0+ (see CMakeLists.txt): check_no_soft_float.sh then finds no floating-point or
// division routine among the object's symbols. Only these calls live here, so any such
// symbol is theirs.
#include "spanlight/pose.hpp"
#include "spanlight/scene_animation.hpp"

using namespace spanlight;

extern "C" {

// One frame of a baked animation: its pose, then its matrices.
PoseResult arm_live_frame_matrices(const PreparedScene* scene, const SceneAnimation* animation, std::uint32_t frame,
                                   CameraPose* projector_storage, Mat4Block* clip, Mat4Block* light, Mat4Block* texture) {
  const FramePose pose = scene_pose_at_frame(*animation, frame, {projector_storage, animation->projector_count});
  const std::size_t per_projector = projector_matrix_count(*scene);
  const MatrixStorage storage{{clip, clip_matrix_count(*scene)}, {texture, per_projector}, {light, per_projector}};
  return build_frame_matrices(*scene, pose, storage);
}

}  // extern "C"
