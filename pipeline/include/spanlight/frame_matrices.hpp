// What a pose gives one frame: the matrices that take each object's vertices
// to the camera's clip space and to each projector's. `spanlight bake`
// writes a scene's own as constants; firmware that moves the camera, an object
// or a light builds them between frames (pose.hpp) without re-baking.
#pragma once

#include "fixedpoint/vec.hpp"

namespace spanlight {

using fixedpoint::Mat4Block;

struct FrameMatrices {
  const Mat4Block* clip_from_object;        // [object]: P * V * M
  const Mat4Block* projector_from_object;   // [object * projector_count + j]: B * P_j * V_j * M
  const Mat4Block* light_clip_from_object;  // [object * projector_count + j]: P_j * V_j * M (shadow maps)
};

}  // namespace spanlight
