#include "prepare/prepare_animation.hpp"

#include <span>

#include "fixedpoint/perspective.hpp"
#include "fixedpoint/pose_status.hpp"

namespace spanlight::prepare {
namespace {

fixedpoint::q16 q16_of(double value) { return fixedpoint::q16::from_double(value); }

Mat4Block model_block(const glm::dmat4& m) {
  double col_major[16];
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) col_major[c * 4 + r] = m[c][r];
  return fixedpoint::mat4_block_from_doubles(col_major);
}

std::string quoted_name(const std::string& name, const char* list, int index) {
  const std::string where = std::string(list) + "[" + std::to_string(index) + "]";
  return name.empty() ? where : "\"" + name + "\" (" + where + ")";
}

}  // namespace

CameraPose camera_lens(const scene::Scene& s) {
  return {{}, {static_cast<std::uint32_t>(s.width), static_cast<std::uint32_t>(s.height)}, q16_of(s.camera.near), q16_of(s.camera.far)};
}

CameraPose projector_lens(const scene::Projector& p) {
  return {{}, fixedpoint::aspect_from_q16(q16_of(p.aspect)), q16_of(p.near), q16_of(p.far)};
}

std::unique_ptr<PreparedAnimation> prepare_animation(const scene::Scene& scene, const scene::Animation& animation) {
  auto out = std::make_unique<PreparedAnimation>();
  out->source = animation;
  const auto animated = [](const scene::AnimatedView& view, const CameraPose& lens) {
    return AnimatedCamera{view.track(), lens.aspect, lens.near, lens.far};
  };
  for (std::size_t j = 0; j < scene.projectors.size(); ++j)
    out->projectors.push_back(animated(out->source.projectors[j], projector_lens(scene.projectors[j])));
  for (const scene::Object& o : scene.objects) out->models.push_back(model_block(o.model));
  out->animation = SceneAnimation{animation.frame_count,
                                  animated(out->source.camera, camera_lens(scene)),
                                  out->projectors.data(),
                                  static_cast<std::uint8_t>(out->projectors.size()),
                                  out->models.data(),
                                  static_cast<std::uint16_t>(out->models.size())};
  return out;
}

PosedMatrices::PosedMatrices(const PreparedScene& scene)
    : clip_from_object(clip_matrix_count(scene)),
      projector_from_object(projector_matrix_count(scene)),
      light_clip_from_object(projector_matrix_count(scene)) {}

PoseResult pose_frame(const PreparedScene& scene, const SceneAnimation& animation, std::uint32_t frame, PosedMatrices& out) {
  std::vector<CameraPose> projectors(animation.projector_count);
  const FramePose pose = scene_pose_at_frame(animation, frame, projectors);
  return build_frame_matrices(scene, pose, out.storage());
}

std::string describe_pose_failure(const PoseResult& r, const std::vector<std::string>& object_names, const scene::Scene& scene) {
  std::string text;
  if (r.object >= 0) {
    const auto i = static_cast<std::size_t>(r.object);
    text = "object " + quoted_name(i < object_names.size() ? object_names[i] : "", "objects", r.object);
    if (r.failure != PoseFailure::model) text += " seen by ";
  }
  if (r.failure == PoseFailure::camera) text += "the camera";
  if (r.failure == PoseFailure::projector) {
    const auto j = static_cast<std::size_t>(r.projector);
    text += "projector " + quoted_name(j < scene.projectors.size() ? scene.projectors[j].name : "", "projectors", r.projector);
  }
  if (r.failure == PoseFailure::pose_too_small || r.failure == PoseFailure::storage_too_small) return describe(r.failure);
  return text + ": " + fixedpoint::pose_status_name(r.status);
}

void check_every_frame(const PreparedStorage& prepared, const PreparedAnimation& animation, const scene::Scene& scene) {
  PosedMatrices matrices(prepared.scene);
  for (std::uint32_t k = 0; k < animation.animation.frame_count; ++k) {
    const PoseResult r = pose_frame(prepared.scene, animation.animation, k, matrices);
    if (r.ok()) continue;
    throw PrepareError(animation.source.file.string() + ": frames[" + std::to_string(k) +
                       "]: expected a pose the pipeline can build, got " + describe_pose_failure(r, prepared.object_names, scene));
  }
}

}  // namespace spanlight::prepare
