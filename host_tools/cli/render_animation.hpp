// spanlight render SCENE --animation A --backend fixed|float|both --out DIR: every frame
// of an animation (docs/animation-format.md) as DIR/<backend>/frame_NNNN.png, through
// io::OutputFolder. The fixed backend plays the animation as the firmware does
// (scene_pose_at_frame, build_frame_matrices); the float model renders each frame's
// scene (scene_at_frame). With both, each frame's PSNR goes to stdout and compare/psnr.csv.
#pragma once

#include <string>

#include "spanlight/knobs.hpp"

namespace spanlight::cli {

struct AnimationRender {
  std::string scene, animation, backend, out;
  Knobs knobs;
  bool force = false;
};

int run_render_animation(const AnimationRender& request);

}  // namespace spanlight::cli
