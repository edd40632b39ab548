// Animation files (docs/animation-format.md): the example plays as pose_at_frame says
// and scene_at_frame carries those poses exactly; every file of the malformed corpus
// (bad_animations/, README.md there) is refused with a SceneError naming file and field.
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "fixedpoint/look_at.hpp"
#include "scene/animation.hpp"
#include "scene/scene.hpp"
#include "source_paths.hpp"

using namespace spanlight::scene;
using spanlight::scene::test::source_dir;

namespace {

std::filesystem::path bad_animation_dir() { return source_dir() / "tests" / "scene" / "bad_animations"; }

fixedpoint::Vec3Q16 to_q16(const glm::dvec3& v) { return fixedpoint::vec3_q16(v.x, v.y, v.z); }

// Exact: a pose in a frame's scene is a Q15.16 value held in a double.
void require_pose(const glm::dvec3& eye, const glm::dvec3& target, const glm::dvec3& up, double fovy_deg,
                  const fixedpoint::ViewPose& expected) {
  const auto same = [](const fixedpoint::Vec3Q16& a, const fixedpoint::Vec3Q16& b) { return a.x == b.x && a.y == b.y && a.z == b.z; };
  REQUIRE(same(to_q16(eye), expected.eye));
  REQUIRE(same(to_q16(target), expected.target));
  REQUIRE(same(to_q16(up), expected.up));
  REQUIRE(fixedpoint::turns_from_degrees(fovy_deg) == expected.fovy);
  REQUIRE(std::ldexp(static_cast<double>(expected.eye.x), -16) == eye.x);  // nothing lost on the way
}

struct BadAnimation {
  const char* file;        // under tests/scene/bad_animations/
  const char* scene;       // under tests/scene/bad_animations/scenes/
  const char* field;       // SceneError::field(), exactly
  bool scene_at_fault;     // the error names the scene file instead of the animation
};

// clang-format off
const std::vector<BadAnimation> bad_animations = {
  // the document
  {"invalid_json.json",                      "base.json", "(root)",                              false},
  {"root_not_object.json",                   "base.json", "(root)",                              false},
  {"number_overflow.json",                   "base.json", "frames",                              false},
  {"duplicate_key.json",                     "base.json", "frames",                              false},
  {"version_missing.json",                   "base.json", "spanlight_animation",                 false},
  {"version_2.json",                         "base.json", "spanlight_animation",                 false},
  {"unknown_top_level_field.json",           "base.json", "lights",                              false},
  // frames
  {"frames_missing.json",                    "base.json", "frames",                              false},
  {"frames_0.json",                          "base.json", "frames",                              false},
  {"frames_fractional.json",                 "base.json", "frames",                              false},
  {"frames_65537.json",                      "base.json", "frames",                              false},
  // tracks
  {"track_neither.json",                     "base.json", "camera",                              false},
  {"track_both.json",                        "base.json", "camera.orbit",                        false},
  {"unknown_track_field.json",               "base.json", "camera.speed",                        false},
  {"projector_unknown.json",                 "base.json", "projectors.lamp",                     false},
  {"projectors_not_object.json",             "base.json", "projectors",                          false},
  // key frames
  {"keys_empty.json",                        "base.json", "camera.keys",                         false},
  {"keys_not_array.json",                    "base.json", "camera.keys",                         false},
  {"key_frame_missing.json",                 "base.json", "camera.keys[0].frame",                false},
  {"key_frame_negative.json",                "base.json", "camera.keys[0].frame",                false},
  {"key_frame_60_of_60.json",                "base.json", "camera.keys[1].frame",                false},
  {"key_frames_not_increasing.json",         "base.json", "camera.keys[1].frame",                false},
  {"key_eye_missing.json",                   "base.json", "camera.keys[0].eye",                  false},
  {"key_eye_two_numbers.json",               "base.json", "camera.keys[0].eye",                  false},
  {"key_eye_16384.json",                     "base.json", "camera.keys[0].eye[0]",               false},
  {"key_target_rounds_to_16384.json",        "base.json", "camera.keys[0].target[2]",            false},
  {"key_fovy_180.json",                      "base.json", "camera.keys[1].fovy_deg",             false},
  {"key_fovy_0_001.json",                    "base.json", "camera.keys[0].fovy_deg",             false},
  {"unknown_key_field.json",                 "base.json", "camera.keys[0].roll",                 false},
  // views that are not views at some frame
  {"key_eye_equals_target.json",             "base.json", "camera.keys",                         false},
  {"keys_pass_through_target.json",          "base.json", "camera.keys",                         false},
  {"key_up_parallel.json",                   "base.json", "camera.keys",                         false},
  {"orbit_looks_along_up.json",              "base.json", "projectors.spot.orbit",               false},
  // orbits
  {"orbit_radius_negative.json",             "base.json", "projectors.spot.orbit.radius",        false},
  {"orbit_radius_leaves_range.json",         "base.json", "projectors.spot.orbit.radius",        false},
  {"orbit_center_missing.json",              "base.json", "projectors.spot.orbit.center",        false},
  {"orbit_turns_fractional.json",            "base.json", "projectors.spot.orbit.turns",         false},
  {"orbit_turns_2000.json",                  "base.json", "projectors.spot.orbit.turns",         false},
  {"orbit_start_400.json",                   "base.json", "projectors.spot.orbit.start_deg",     false},
  {"unknown_orbit_field.json",               "base.json", "projectors.spot.orbit.height",        false},
  // what the animation keeps from the scene must fit the fixed-point formats too
  {"scene_camera_beyond_range.json",         "far_camera.json",                "camera.eye",          true},
  {"scene_camera_fovy_beyond_range.json",    "wide_fovy.json",                 "camera.fovy_deg",     true},
  {"scene_projector_target_rounds_to_eye.json", "fill_target_rounds_to_eye.json", "projectors[1]",    true},
  {"scene_projector_name_shared.json",       "twin_projectors.json",           "projectors.spot",     false},
};
// clang-format on

}  // namespace

TEST_CASE("the example animation plays pose_at_frame's poses, and scene_at_frame holds them exactly", "[scene][animation]") {
  const Scene scene = load_scene(source_dir() / "scenes" / "spot_shadow.json");
  const Animation animation = load_animation(source_dir() / "scenes" / "animations" / "spot_orbit.json", scene);
  REQUIRE(animation.frame_count == 60);
  REQUIRE(animation.camera.keys.size() == 2);
  REQUIRE(animation.projectors.size() == 1);
  REQUIRE(animation.projectors[0].keys.empty());  // an orbit
  for (std::uint32_t frame = 0; frame < animation.frame_count; ++frame) {
    INFO("frame " << frame);
    const Scene at = scene_at_frame(scene, animation, frame);
    require_pose(at.camera.eye, at.camera.target, at.camera.up, at.camera.fovy_deg,
                 fixedpoint::pose_at_frame(animation.camera.track(), frame, 60));
    const Projector& spot = at.projectors[0];
    require_pose(spot.eye, spot.target, spot.up, spot.fovy_deg, fixedpoint::pose_at_frame(animation.projectors[0].track(), frame, 60));
    // The orbit: radius 3 around (-0.2, 5, -0.4), within the sine's error and the Q15.16 rounding.
    REQUIRE(std::hypot(spot.eye.x + 0.2, spot.eye.z + 0.4) == Approx(3.0).margin(2.0 / 65536));
    REQUIRE(spot.eye.y == 5.0);
    // What the animation does not move stays as the scene has it.
    REQUIRE(at.camera.near == scene.camera.near);
    REQUIRE(spot.near == scene.projectors[0].near);
    REQUIRE(at.objects.size() == scene.objects.size());
  }
  const Scene first = scene_at_frame(scene, animation, 0), last = scene_at_frame(scene, animation, 59);
  REQUIRE(first.camera.eye == glm::dvec3(0.0, 3.0, 7.0));  // exact in Q15.16
  REQUIRE(last.camera.eye == glm::dvec3(2.5, 2.5, 6.0));
  // The scene's fovy where a key gives none, rounded to Turns (45 degrees is exact there, 50 and 60 are not).
  REQUIRE(first.camera.fovy_deg == fixedpoint::degrees(fixedpoint::turns_from_degrees(50.0)));
  REQUIRE(first.camera.fovy_deg != 50.0);
  REQUIRE(last.camera.fovy_deg == 45.0);
  REQUIRE(first.projectors[0].fovy_deg == fixedpoint::degrees(fixedpoint::turns_from_degrees(60.0)));
  REQUIRE_THROWS_AS(scene_at_frame(scene, animation, 60), std::out_of_range);
}

TEST_CASE("a view the animation does not move keeps the scene's pose, rounded to Q15.16", "[scene][animation]") {
  const Scene scene = load_scene(bad_animation_dir() / "scenes" / "base.json");
  const Animation animation = load_animation(bad_animation_dir() / "scene_projector_target_rounds_to_eye.json",
                                             load_scene(bad_animation_dir() / "scenes" / "base.json"));
  REQUIRE(animation.projectors.size() == 2);
  REQUIRE(animation.projectors[1].keys.size() == 1);
  const Scene at = scene_at_frame(scene, animation, 17);
  REQUIRE(at.projectors[1].eye == scene.projectors[1].eye);  // (-2, 4, 2): exact in Q15.16
  REQUIRE(at.projectors[1].fovy_deg == fixedpoint::degrees(fixedpoint::turns_from_degrees(40.0)));
}

TEST_CASE("every malformed animation is refused with its file and field", "[scene][animation][bad]") {
  for (const BadAnimation& bad : bad_animations) {
    DYNAMIC_SECTION(bad.file) {
      const auto file = bad_animation_dir() / bad.file;
      const auto scene_file = bad_animation_dir() / "scenes" / bad.scene;
      const Scene scene = load_scene(scene_file);
      try {
        load_animation(file, scene);
        FAIL(bad.file << " loaded without an error");
      } catch (const SceneError& error) {
        INFO(error.what());
        CHECK(error.field() == bad.field);
        CHECK(error.file() == (bad.scene_at_fault ? scene_file : file).string());
        CHECK(error.asset().empty());
        CHECK_THAT(error.expected(), Catch::StartsWith("expected "));
        CHECK(std::string(error.what()) == error.file() + ": " + error.field() + ": " + error.expected());
      }
    }
  }
}

TEST_CASE("the bad-animation table lists every file of the corpus", "[scene][animation][bad]") {
  std::set<std::string> in_table;
  for (const BadAnimation& bad : bad_animations) in_table.insert(bad.file);
  CHECK(in_table.size() == bad_animations.size());
  for (const auto& entry : std::filesystem::directory_iterator(bad_animation_dir())) {
    if (entry.path().extension() != ".json") continue;
    INFO(entry.path().filename().string());
    CHECK(in_table.count(entry.path().filename().string()) == 1);
  }
}

TEST_CASE("an animation's messages say what was expected and what was found", "[scene][animation][bad]") {
  const Scene scene = load_scene(bad_animation_dir() / "scenes" / "base.json");
  const auto message = [&](const char* file) {
    try {
      load_animation(bad_animation_dir() / file, scene);
    } catch (const SceneError& error) {
      return error.expected();
    }
    return std::string("no error");
  };
  CHECK(message("keys_pass_through_target.json") == "expected a valid view at every frame, got eye equals target at frame 29");
  CHECK(message("projector_unknown.json") == "expected the name of a projector of the scene (spot, fill), got lamp");
  CHECK(message("key_frames_not_increasing.json") == "expected a frame after the previous key's 0, got 0");
  CHECK(message("key_fovy_180.json") == "expected a number in [0.0054931640625, 179.9945068359375], got 180");
  CHECK_THAT(message("no_such_animation.json"), Catch::Contains("no such file"));
}
