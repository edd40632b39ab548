// An animation file (docs/animation-format.md): how the camera and the projectors
// of a scene move over a number of frames. The poses are kept in the firmware's
// fixed-point formats and played by fixedpoint::pose_at_frame, the function the
// firmware runs, so the scene of frame k (scene_at_frame) holds exactly the poses
// the target builds its matrices from.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "fixedpoint/pose_at_frame.hpp"
#include "scene/scene.hpp"

namespace spanlight::scene {

// One camera's or projector's motion: key frames, or (keys empty) an orbit. A view the
// file does not animate holds its scene pose as a single key.
struct AnimatedView {
  std::vector<fixedpoint::KeyFrame> keys;
  fixedpoint::Orbit orbit{};

  fixedpoint::PoseTrack track() const {
    return {keys.empty() ? nullptr : keys.data(), static_cast<std::uint32_t>(keys.size()), orbit};
  }
};

struct Animation {
  std::filesystem::path file;
  std::uint32_t frame_count = 1;
  AnimatedView camera;
  std::vector<AnimatedView> projectors;  // one per projector of the scene, in its order
};

// Parses and validates an animation of `scene`: every pose within the fixed-point ranges
// and a valid view (look_at accepts it) at every frame. Throws SceneError naming the
// animation file and field, or the scene file and field when a pose the animation keeps
// from the scene does not fit the fixed-point formats.
Animation load_animation(const std::filesystem::path& file, const Scene& scene);

// The scene at frame `frame` (0 .. frame_count - 1) of the animation: the camera's and
// projectors' eye, target, up and fovy replaced by the animation's fixed-point poses (as
// doubles, exactly); everything else as in `scene`.
Scene scene_at_frame(const Scene& scene, const Animation& animation, std::uint32_t frame);

}  // namespace spanlight::scene
