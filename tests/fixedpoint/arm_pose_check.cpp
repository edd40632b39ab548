// The run-time pose builders as firmware calls them, compiled for Cortex-M0+ and
// M7 (see CMakeLists.txt): they build freestanding with -fno-exceptions -fno-rtti
// and -Werror, and on M0+ check_no_soft_float.sh finds no floating-point or
// division routine among the object's symbols. Only the builders live here, so
// any such symbol is theirs.
#include "fixedpoint/look_at.hpp"
#include "fixedpoint/mat4.hpp"
#include "fixedpoint/perspective.hpp"
#include "fixedpoint/pose_at_frame.hpp"

using namespace fixedpoint;

// A demo frame's matrices: a camera and one projector over a model matrix, the poses from tracks.
extern "C" {

PoseStatus arm_frame_matrices(const PoseTrack* camera, const PoseTrack* projector, std::uint32_t frame,
                              std::uint32_t frame_count, const Mat4Block* model, Mat4Block* clip_from_object,
                              Mat4Block* light_clip_from_object, Mat4Block* projector_from_object) {
  const ViewPose c = pose_at_frame(*camera, frame, frame_count);
  const ViewPose p = pose_at_frame(*projector, frame, frame_count);
  const q16 near = q16::from_raw(6554), far = q16::from_int(40);
  const Mat4 m = mat4(*model);
  const BlockResult clip = pipeline_matrix(perspective(c.fovy, Aspect{320, 240}, near, far) * (look_at(c.eye, c.target, c.up) * m));
  const Mat4 light = perspective(p.fovy, aspect_from_q16(q16::from_int(1)), near, far) * (look_at(p.eye, p.target, p.up) * m);
  const BlockResult light_clip = pipeline_matrix(light);
  const BlockResult texture = pipeline_matrix(bias() * light);
  *clip_from_object = clip.block;
  *light_clip_from_object = light_clip.block;
  *projector_from_object = texture.block;
  if (clip.status != PoseStatus::ok) return clip.status;
  return light_clip.status != PoseStatus::ok ? light_clip.status : texture.status;
}

Mat4 arm_view_matrix(const Vec3Q16* eye, const Vec3Q16* target, const Vec3Q16* up) { return mat4(look_at(*eye, *target, *up)); }

SinCos arm_sin_cos(std::uint32_t angle) { return sin_cos(Turns{angle}); }

}  // extern "C"
