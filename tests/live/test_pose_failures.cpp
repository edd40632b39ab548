// build_frame_matrices names what failed: the status, the camera or projector j,
// the object, or arrays too small; and render_frame_at_pose refuses such a pose with
// RenderStatus::bad_pose before it writes a byte of colour, depth or shadow map or
// calls a hook.
#include <catch2/catch.hpp>

#include <vector>

#include "live_support.hpp"
#include "spanlight/pose.hpp"

namespace {

using namespace spanlight;
using fixedpoint::PoseStatus;

struct Fixture {
  live_test::Loaded l = live_test::load("live_spotlight.json", "live_spotlight.json");
  std::vector<CameraPose> projectors = std::vector<CameraPose>(1);
  FramePose pose = scene_pose_at_frame(l.prepared_animation->animation, 0, projectors);
  std::vector<Mat4Block> models = std::vector<Mat4Block>(pose.models.begin(), pose.models.end());
  prepare::PosedMatrices built{l.prepared->scene};

  Fixture() { pose.models = models; }
  PoseResult build() { return build_frame_matrices(l.prepared->scene, pose, built.storage()); }
};

// A model matrix that scales by 2^14: V * M has entries beyond the pipeline's 2^13.
Mat4Block huge_scale() {
  const double m[16] = {16384, 0, 0, 0, 0, 16384, 0, 0, 0, 0, 16384, 0, 0, 0, 0, 1};
  return fixedpoint::mat4_block_from_doubles(m);
}

}  // namespace

TEST_CASE("live: a good pose builds") {
  Fixture f;
  const PoseResult r = f.build();
  CHECK(r.ok());
  CHECK(r.status == PoseStatus::ok);
}

TEST_CASE("live: each pose failure is named") {
  Fixture f;
  SECTION("camera: eye equals target") {
    f.pose.camera.view.target = f.pose.camera.view.eye;
    const PoseResult r = f.build();
    CHECK(r.failure == PoseFailure::camera);
    CHECK(r.status == PoseStatus::eye_equals_target);
    CHECK(r.object == -1);
  }
  SECTION("camera: swapped near and far") {
    std::swap(f.pose.camera.near, f.pose.camera.far);
    const PoseResult r = f.build();
    CHECK(r.failure == PoseFailure::camera);
    CHECK(r.status == PoseStatus::far_not_beyond_near);
  }
  SECTION("projector 0: fovy 0") {
    f.projectors[0].view.fovy = fixedpoint::Turns{0};
    const PoseResult r = f.build();
    CHECK(r.failure == PoseFailure::projector);
    CHECK(r.projector == 0);
    CHECK(r.status == PoseStatus::fovy_out_of_range);
    CHECK(r.object == -1);
  }
  SECTION("projector 0: up parallel to the view") {
    const auto& v = f.projectors[0].view;
    f.projectors[0].view.up = {v.target.x - v.eye.x, v.target.y - v.eye.y, v.target.z - v.eye.z};
    const PoseResult r = f.build();
    CHECK(r.failure == PoseFailure::projector);
    CHECK(r.status == PoseStatus::up_parallel_to_view);
  }
  SECTION("object 2 seen by the camera: beyond the pipeline's range") {
    f.models[2] = huge_scale();
    const PoseResult r = f.build();
    CHECK(r.failure == PoseFailure::camera);
    CHECK(r.object == 2);
    CHECK(r.status == PoseStatus::beyond_pipeline_range);
  }
  SECTION("object 0 seen by projector 0 at its narrowest fovy") {
    // The camera's matrices are fine; the projector's P00 = cot(fovy/2) is near 2^14.35 at the
    // smallest fovy, so the first object's light matrix has entries beyond 2^13.
    f.projectors[0].view.fovy = fixedpoint::Turns{fixedpoint::min_fovy_raw};
    const PoseResult r = f.build();
    CHECK(r.failure == PoseFailure::projector);
    CHECK(r.projector == 0);
    CHECK(r.object == 0);
    CHECK(r.status == PoseStatus::beyond_pipeline_range);
  }
  SECTION("object 1's model is not a Mat4Block") {
    f.models[1].frac_bits = 61;
    const PoseResult r = f.build();
    CHECK(r.failure == PoseFailure::model);
    CHECK(r.object == 1);
    CHECK(r.status == PoseStatus::entry_out_of_range);
  }
  SECTION("fewer models than objects") {
    f.pose.models = f.pose.models.first(2);
    CHECK(f.build().failure == PoseFailure::pose_too_small);
  }
  SECTION("no projector poses") {
    f.pose.projectors = {};
    CHECK(f.build().failure == PoseFailure::pose_too_small);
  }
  SECTION("storage too small") {
    f.built.light_clip_from_object.pop_back();
    CHECK(f.build().failure == PoseFailure::storage_too_small);
  }
}

namespace {

// Counts every hook the pipeline calls.
struct CountingHooks : NoHooks {
  int* calls;
  void pass_begin(Pass, int) { ++*calls; }
  void pass_end(Pass, int) { ++*calls; }
  void touched(Pass, std::uint32_t) { ++*calls; }
  void triangle_begin() { ++*calls; }
  void triangle_rows() { ++*calls; }
  template <typename Storage>
  void band_done(std::uint16_t, std::uint16_t, const Storage*) { ++*calls; }
};

constexpr Features demo_features = host_features(PixelFormat::rgb565);

}  // namespace

TEST_CASE("live: a bad pose leaves colour, depth and shadow map untouched and calls no hook") {
  Fixture f;
  f.pose.camera.view.up = {0, 0, 0};
  const PreparedScene& scene = f.l.prepared->scene;
  const std::size_t band = std::size_t{scene.width} * 16;
  std::vector<std::uint16_t> color(band, 0xA5A5), depth(band, 0x5A5A), map(128 * 128, 0x1234);
  std::vector<std::uint8_t> tie(tie_mask_bytes(static_cast<std::uint32_t>(band)), 0x77);
  std::vector<CachedVertex> vertices(scene.max_vertex_count);
  const std::span<std::uint16_t> maps[1] = {map};
  const FrameTarget<PixelFormat::rgb565, std::uint16_t> target{color, depth, maps, tie, vertices, 16};
  Knobs knobs;
  knobs.format = PixelFormat::rgb565;
  knobs.depth_bits = 16;
  int calls = 0;
  PoseResult why;
  const RenderStatus s = render_frame_at_pose<demo_features>(scene, f.pose, f.built.storage(), target, knobs, why, CountingHooks{{}, &calls});
  CHECK(s == RenderStatus::bad_pose);
  CHECK(why.failure == PoseFailure::camera);
  CHECK(why.status == PoseStatus::up_is_zero);
  CHECK(calls == 0);
  CHECK(std::all_of(color.begin(), color.end(), [](std::uint16_t c) { return c == 0xA5A5; }));
  CHECK(std::all_of(depth.begin(), depth.end(), [](std::uint16_t d) { return d == 0x5A5A; }));
  CHECK(std::all_of(map.begin(), map.end(), [](std::uint16_t d) { return d == 0x1234; }));
  CHECK(std::all_of(tie.begin(), tie.end(), [](std::uint8_t b) { return b == 0x77; }));

  // The same target at a good pose renders, and calls the hooks: the check above is not vacuous.
  f.pose.camera.view.up = {0, 65536, 0};
  CHECK(render_frame_at_pose<demo_features>(scene, f.pose, f.built.storage(), target, knobs, why, CountingHooks{{}, &calls}) == RenderStatus::ok);
  CHECK(calls > 0);
  CHECK(std::any_of(map.begin(), map.end(), [](std::uint16_t d) { return d != 0x1234; }));
}
