// A baked animation (`spanlight bake --animation`, docs/live-scenes.md): how the camera
// and the projectors move over frame_count frames, and what stays (each view's
// frustum, each object's model matrix). scene_pose_at_frame gives frame k's FramePose;
// the host's `spanlight render --animation` and the firmware both call it, so they
// build the same matrices to the bit (fixedpoint::pose_at_frame is integer-only).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "fixedpoint/pose_at_frame.hpp"
#include "spanlight/pose.hpp"

namespace spanlight {

// One camera's or projector's motion and its fixed frustum.
struct AnimatedCamera {
  fixedpoint::PoseTrack track;  // key frames or an orbit (fixedpoint/pose_at_frame.hpp)
  fixedpoint::Aspect aspect;
  fixedpoint::q16 near, far;
};

struct SceneAnimation {
  std::uint32_t frame_count;            // frames 0 .. frame_count - 1
  AnimatedCamera camera;
  const AnimatedCamera* projectors;     // projector_count, in the PreparedScene's order
  std::uint8_t projector_count;
  const Mat4Block* models;              // object_count, in the PreparedScene's order: still
  std::uint16_t object_count;
};

// Frame `frame`'s pose. The projectors' poses go to the caller's `projectors` (one per
// projector); the FramePose points into it and into animation.models. A storage shorter
// than the animation's projectors gives a pose that build_frame_matrices refuses
// (PoseFailure::pose_too_small). A frame beyond the last holds the last key's pose (keys)
// or goes on around the orbit.
constexpr FramePose scene_pose_at_frame(const SceneAnimation& animation, std::uint32_t frame,
                                        std::span<CameraPose> projectors) {
  const auto posed = [&](const AnimatedCamera& c) {
    return CameraPose{fixedpoint::pose_at_frame(c.track, frame, animation.frame_count), c.aspect, c.near, c.far};
  };
  const std::size_t count = projectors.size() < animation.projector_count ? projectors.size() : animation.projector_count;
  for (std::size_t j = 0; j < count; ++j) projectors[j] = posed(animation.projectors[j]);
  return {posed(animation.camera), {animation.models, animation.object_count}, projectors.first(count)};
}

}  // namespace spanlight
