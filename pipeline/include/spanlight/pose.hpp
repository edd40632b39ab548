// Run-time poses: the matrices of one frame built on the target from where the
// camera, each object and each projector are, with the integer pose builders of
// fixedpoint/ (docs/poses.md), so firmware moves things without re-baking:
//
//   const PoseResult r = build_frame_matrices(scene, pose, storage);
//   if (r.ok()) render_frame<F>(scene, storage.matrices(), target, knobs);
//
// or render_frame_at_pose (below), which does both and refuses a bad pose
// with RenderStatus::bad_pose before it writes a byte. Per object i and projector j:
//   clip_from_object[i]                           = P   * (V   * M_i)
//   light_clip_from_object[i * projectors + j]    = P_j * (V_j * M_i)
//   projector_from_object[i * projectors + j]     = B * P_j * (V_j * M_i)
// each rounded once to the pipeline's Mat4Block (pipeline_matrix). The order
// P * (V * M) keeps V * M eye-relative (look_at.hpp); docs/poses.md gives the bounds.
// Nothing here allocates: the matrices go to the caller's MatrixStorage.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "fixedpoint/look_at.hpp"
#include "fixedpoint/mat4.hpp"
#include "fixedpoint/perspective.hpp"
#include "fixedpoint/pose_at_frame.hpp"
#include "fixedpoint/pose_status.hpp"
#include "spanlight/frame_matrices.hpp"
#include "spanlight/frame_target.hpp"
#include "spanlight/hooks.hpp"
#include "spanlight/knobs.hpp"
#include "spanlight/render.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

using fixedpoint::PoseStatus;

// A camera's or projector's pose and frustum for one frame. The camera's aspect is
// {width, height} of the frame; a projector's, fixedpoint::aspect_from_q16(aspect).
struct CameraPose {
  fixedpoint::ViewPose view;  // eye, target, up (Q15.16 world units), fovy (Turns)
  fixedpoint::Aspect aspect;
  fixedpoint::q16 near, far;
};

// Everything that moves in one frame.
struct FramePose {
  CameraPose camera;
  std::span<const Mat4Block> models;    // one per object, in the PreparedScene's order
  std::span<const CameraPose> projectors; // one per projector
};

// The caller's arrays for one frame's matrices (frame_matrices.hpp's layout).
struct MatrixStorage {
  std::span<Mat4Block> clip_from_object;        // object_count
  std::span<Mat4Block> projector_from_object;   // object_count * projector_count
  std::span<Mat4Block> light_clip_from_object;  // object_count * projector_count

  FrameMatrices matrices() const {
    return {clip_from_object.data(), projector_from_object.data(), light_clip_from_object.data()};
  }
};

// Blocks a scene's frame needs in each array of MatrixStorage.
constexpr std::size_t clip_matrix_count(const PreparedScene& scene) { return scene.object_count; }
constexpr std::size_t projector_matrix_count(const PreparedScene& scene) {
  return std::size_t{scene.object_count} * scene.projector_count;
}

// Where a pose failed.
enum class PoseFailure : std::uint8_t {
  none,
  model,              // models[object] is not a valid Mat4Block (fixedpoint::mat4)
  camera,             // the camera's view or frustum, or (object >= 0) its matrices for that object
  projector,          // projector `projector`'s, likewise
  pose_too_small,     // fewer models or projectors in the pose than the scene has
  storage_too_small,  // a MatrixStorage array shorter than clip_/projector_matrix_count
};

struct PoseResult {
  PoseStatus status = PoseStatus::ok;  // what the builder reported (ok for the two *_too_small)
  PoseFailure failure = PoseFailure::none;
  int projector = -1;  // the failing projector, for PoseFailure::projector
  int object = -1;     // the object whose matrix failed; -1 when the view or frustum itself did

  constexpr bool ok() const { return failure == PoseFailure::none; }
};

constexpr const char* describe(PoseFailure f) {
  switch (f) {
    case PoseFailure::none: return "ok";
    case PoseFailure::model: return "an object's model matrix is not a valid Mat4Block";
    case PoseFailure::camera: return "the camera's pose";
    case PoseFailure::projector: return "a projector's pose";
    case PoseFailure::pose_too_small: return "the pose has fewer models or projectors than the scene";
    case PoseFailure::storage_too_small: return "the matrix storage is smaller than the scene's matrices";
  }
  return "unknown";
}

namespace detail {

// The view and frustum of one camera or projector, built once a frame.
struct BuiltView {
  fixedpoint::View view;
  fixedpoint::Mat4 projection;
  PoseStatus status;
};

constexpr BuiltView build_view(const CameraPose& p) {
  BuiltView b{fixedpoint::look_at(p.view.eye, p.view.target, p.view.up),
              fixedpoint::perspective(p.view.fovy, p.aspect, p.near, p.far), PoseStatus::ok};
  b.status = b.view.status != PoseStatus::ok ? b.view.status : b.projection.status;
  return b;
}

}  // namespace detail

// Fills `out` with the frame's matrices, or says what failed (the first failure in the
// order: sizes, models, the camera's view, its matrices object by object, then each
// projector's view and matrices). After a failure the
// storage holds nothing usable. Integer arithmetic only: the same bits on every core.
constexpr PoseResult build_frame_matrices(const PreparedScene& scene, const FramePose& pose, const MatrixStorage& out) {
  const int projectors = scene.projector_count;
  if (pose.models.size() < scene.object_count || pose.projectors.size() < std::size_t(projectors))
    return {PoseStatus::ok, PoseFailure::pose_too_small};
  if (out.clip_from_object.size() < clip_matrix_count(scene) ||
      out.projector_from_object.size() < projector_matrix_count(scene) ||
      out.light_clip_from_object.size() < projector_matrix_count(scene))
    return {PoseStatus::ok, PoseFailure::storage_too_small};

  for (int i = 0; i < scene.object_count; ++i) {
    const PoseStatus s = fixedpoint::mat4(pose.models[std::size_t(i)]).status;
    if (s != PoseStatus::ok) return {s, PoseFailure::model, -1, i};
  }
  const detail::BuiltView camera = detail::build_view(pose.camera);
  if (camera.status != PoseStatus::ok) return {camera.status, PoseFailure::camera};

  for (int i = 0; i < scene.object_count; ++i) {
    const fixedpoint::Mat4 model = fixedpoint::mat4(pose.models[std::size_t(i)]);
    const fixedpoint::BlockResult clip = fixedpoint::pipeline_matrix(camera.projection * (camera.view * model));
    if (clip.status != PoseStatus::ok) return {clip.status, PoseFailure::camera, -1, i};
    out.clip_from_object[std::size_t(i)] = clip.block;
  }
  const fixedpoint::Mat4 bias = fixedpoint::bias();
  for (int j = 0; j < projectors; ++j) {
    const detail::BuiltView light_view = detail::build_view(pose.projectors[std::size_t(j)]);
    if (light_view.status != PoseStatus::ok) return {light_view.status, PoseFailure::projector, j};
    for (int i = 0; i < scene.object_count; ++i) {
      const fixedpoint::Mat4 light = light_view.projection * (light_view.view * fixedpoint::mat4(pose.models[std::size_t(i)]));
      const fixedpoint::BlockResult light_clip = fixedpoint::pipeline_matrix(light);
      const fixedpoint::BlockResult texture = fixedpoint::pipeline_matrix(bias * light);
      const PoseStatus s = light_clip.status != PoseStatus::ok ? light_clip.status : texture.status;
      if (s != PoseStatus::ok) return {s, PoseFailure::projector, j, i};
      const std::size_t k = std::size_t(i) * std::size_t(projectors) + std::size_t(j);
      out.light_clip_from_object[k] = light_clip.block;
      out.projector_from_object[k] = texture.block;
    }
  }
  return {};
}

// render_frame at a run-time pose: the matrices are built into `storage` first, and a
// pose they cannot be built from returns RenderStatus::bad_pose (what failed in
// `pose_result`) before a byte of colour, depth or shadow map is written or a hook called.
template <Features F, typename DepthT, typename Hooks = NoHooks>
RenderStatus render_frame_at_pose(const PreparedScene& scene, const FramePose& pose, const MatrixStorage& storage,
                                  const FrameTarget<F.format, DepthT>& target, const Knobs& knobs,
                                  PoseResult& pose_result, Hooks&& hooks = Hooks{}) {
  pose_result = build_frame_matrices(scene, pose, storage);
  if (!pose_result.ok()) return RenderStatus::bad_pose;
  return render_frame<F>(scene, storage.matrices(), target, knobs, static_cast<Hooks&&>(hooks));
}

}  // namespace spanlight
