// Every frame's run-time matrices (scene_pose_at_frame + build_frame_matrices, the
// firmware's calls) against GLM on that frame's scene, each entry within the bound
// derived in live_matrices_reference.hpp; and a deliberately wrong pose (the camera's
// aspect swapped) fails that comparison, so the bound can catch a mistake.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "live_matrices_reference.hpp"
#include "live_support.hpp"
#include "scene/animation.hpp"

namespace {

using namespace spanlight;

struct Case {
  const char* scene;
  const char* animation;
};

constexpr Case cases[] = {{"live_spotlight.json", "live_spotlight.json"}, {"spot_shadow.json", "spot_orbit.json"}};

// Largest |GLM on the frame's scene - the reference's value| relative to the largest entry:
// the reference is that scene's matrix (up to double rounding).
double relative_gap(const glm::dmat4& a, const glm::dmat4& b) {
  return pose_reference::max_abs(a - b) / pose_reference::max_abs(b);
}

}  // namespace

TEST_CASE("live: every frame's matrices are within the derived bound of GLM on that frame's scene") {
  for (const Case& c : cases) {
    INFO(c.scene << " with " << c.animation);
    const live_test::Loaded l = live_test::load(c.scene, c.animation);
    const SceneAnimation& animation = l.prepared_animation->animation;
    const PreparedScene& scene = l.prepared->scene;
    prepare::PosedMatrices built(scene);
    double worst = 0.0;
    for (std::uint32_t k = 0; k < animation.frame_count; ++k) {
      INFO("frame " << k);
      REQUIRE(prepare::pose_frame(scene, animation, k, built).ok());
      std::vector<CameraPose> projectors(animation.projector_count);
      const FramePose pose = scene_pose_at_frame(animation, k, projectors);
      const scene::Scene at = scene::scene_at_frame(l.scene, l.animation, k);
      // The pose is the frame's scene: the same eye, target and up to the bit.
      REQUIRE(pose_reference::to_glm(pose.camera.view.eye) == at.camera.eye);
      REQUIRE(pose_reference::to_glm(pose.camera.view.target) == at.camera.target);
      const scene::Camera& cam = at.camera;
      const glm::dmat4 camera_vp = live_test::glm_view_projection(cam.eye, cam.target, cam.up, cam.fovy_deg,
                                                                  double(at.width) / at.height, cam.near, cam.far);
      for (std::size_t i = 0; i < scene.object_count; ++i) {
        const pose_reference::Expected e = live_test::expected_chain(pose.camera, pose.models[i], built.clip_from_object[i], false);
        REQUIRE(relative_gap(e.value, camera_vp * pose_reference::to_glm(pose.models[i])) < 1e-12);
        const double ratio = pose_reference::compare(built.clip_from_object[i], e).worst_bound_ratio;
        REQUIRE(ratio <= 1.0);
        worst = std::fmax(worst, ratio);
        for (std::size_t j = 0; j < scene.projector_count; ++j) {
          const std::size_t m = i * scene.projector_count + j;
          const scene::Projector& p = at.projectors[j];
          const glm::dmat4 light_vp = live_test::glm_view_projection(p.eye, p.target, p.up, p.fovy_deg,
                                                                     pose.projectors[j].aspect.width / 65536.0, p.near, p.far);
          const pose_reference::Expected light = live_test::expected_chain(pose.projectors[j], pose.models[i], built.light_clip_from_object[m], false);
          const pose_reference::Expected texture = live_test::expected_chain(pose.projectors[j], pose.models[i], built.projector_from_object[m], true);
          REQUIRE(relative_gap(light.value, light_vp * pose_reference::to_glm(pose.models[i])) < 1e-12);
          REQUIRE(pose_reference::compare(built.light_clip_from_object[m], light).worst_bound_ratio <= 1.0);
          REQUIRE(pose_reference::compare(built.projector_from_object[m], texture).worst_bound_ratio <= 1.0);
        }
      }
    }
    UNSCOPED_INFO(c.scene << ": worst clip error / bound " << worst);
  }
}

TEST_CASE("live: a camera with its aspect swapped fails the bound") {
  const live_test::Loaded l = live_test::load("live_spotlight.json", "live_spotlight.json");
  const SceneAnimation& animation = l.prepared_animation->animation;
  const PreparedScene& scene = l.prepared->scene;
  std::vector<CameraPose> projectors(animation.projector_count);
  FramePose pose = scene_pose_at_frame(animation, 17, projectors);
  const CameraPose right = pose.camera;
  std::swap(pose.camera.aspect.width, pose.camera.aspect.height);
  prepare::PosedMatrices wrong(scene);
  REQUIRE(build_frame_matrices(scene, pose, wrong.storage()).ok());
  for (std::size_t i = 0; i < scene.object_count; ++i) {
    const pose_reference::Expected e = live_test::expected_chain(right, pose.models[i], wrong.clip_from_object[i], false);
    CHECK(pose_reference::compare(wrong.clip_from_object[i], e).worst_bound_ratio > 1.0);
  }
}
