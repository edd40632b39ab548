// What a pose builder reports instead of a matrix it cannot make well: the
// singular cases of lookAt and perspective, and inputs or results beyond the
// fixed-point formats (docs/poses.md lists the supported ranges).
#pragma once

#include <cstdint>

namespace fixedpoint {

// Positions, directions and distances given to the builders are Q15.16 with |value| < 2^14,
// as the scene's positions: |raw| < this.
inline constexpr std::int32_t pose_coordinate_limit = std::int32_t{1} << 30;

enum class PoseStatus : std::uint8_t {
  ok,
  coordinate_out_of_range, // a coordinate of eye, target or up, or near or far, with |value| >= 2^14
  eye_equals_target,       // no view direction
  up_is_zero,
  up_parallel_to_view,     // sin(angle between up and target - eye) < 2^-20: the roll is undefined
  fovy_out_of_range,       // fovy outside [2^-16, 1/2 - 2^-16] turn (0.0055 to 179.9945 degrees)
  aspect_not_positive,     // a zero width or height
  near_not_positive,       // near <= 0
  far_not_beyond_near,     // far <= near
  entry_out_of_range,      // a matrix entry with |value| >= 2^29, or a malformed Mat4Block given
  beyond_pipeline_range,   // an entry >= 2^13: clip coordinates could leave Q31.32 (vec.hpp)
};

constexpr const char* pose_status_name(PoseStatus s) {
  switch (s) {
    case PoseStatus::ok: return "ok";
    case PoseStatus::coordinate_out_of_range: return "a coordinate or distance beyond +-16384";
    case PoseStatus::eye_equals_target: return "eye equals target";
    case PoseStatus::up_is_zero: return "up is zero";
    case PoseStatus::up_parallel_to_view: return "up parallel to the view direction";
    case PoseStatus::fovy_out_of_range: return "fovy outside [0.0055, 179.9945] degrees";
    case PoseStatus::aspect_not_positive: return "aspect not positive";
    case PoseStatus::near_not_positive: return "near not positive";
    case PoseStatus::far_not_beyond_near: return "far not beyond near";
    case PoseStatus::entry_out_of_range: return "a matrix entry beyond 2^29";
    case PoseStatus::beyond_pipeline_range: return "a matrix entry beyond the pipeline's 2^13";
  }
  return "unknown";
}

}  // namespace fixedpoint
