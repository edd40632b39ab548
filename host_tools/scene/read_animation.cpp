// load_animation: an animation file (docs/animation-format.md) read into the
// firmware's fixed-point poses, with every error as "FILE: FIELD: expected ...".
#include <cmath>
#include <string>
#include <vector>

#include "fixedpoint/look_at.hpp"
#include "fixedpoint/perspective.hpp"
#include "json_describe.hpp"
#include "json_document.hpp"
#include "json_field.hpp"
#include "scene/animation.hpp"

namespace spanlight::scene {
namespace {

using detail::JsonField;
using fixedpoint::Turns;
using fixedpoint::Vec3Q16;
using fixedpoint::ViewPose;

// The pose builders' ranges (fixedpoint/pose_status.hpp, perspective.hpp), in the file's units.
const double coordinate_limit = std::ldexp(static_cast<double>(fixedpoint::pose_coordinate_limit), -16);  // 16384
const double min_fovy_deg = fixedpoint::degrees(Turns{fixedpoint::min_fovy_raw});
const double max_fovy_deg = fixedpoint::degrees(Turns{fixedpoint::max_fovy_raw});
constexpr std::int64_t max_turns = 1000;

std::string limit_text() { return detail::format_number(coordinate_limit); }

// A coordinate in Q15.16, rounded to nearest; the rounded value must stay inside the builders' range too.
std::int32_t coordinate(const JsonField& field) {
  const double value = field.number(detail::open_interval(-coordinate_limit, coordinate_limit));
  const std::int32_t raw = fixedpoint::q16::from_double(value).raw();
  if (raw <= -fixedpoint::pose_coordinate_limit || raw >= fixedpoint::pose_coordinate_limit) {
    field.fail("expected a number in (-" + limit_text() + ", " + limit_text() + ") after rounding to 1/65536");
  }
  return raw;
}

Vec3Q16 point(const JsonField& field) {
  const auto xyz = field.elements(3, "3 numbers");
  return {coordinate(xyz[0]), coordinate(xyz[1]), coordinate(xyz[2])};
}

// Bounds exact in Turns and rounding monotone, so every fovy inside converts inside.
Turns fovy(const JsonField& field) { return fixedpoint::turns_from_degrees(field.number(detail::closed_interval(min_fovy_deg, max_fovy_deg))); }

Turns fovy_or(const JsonField& owner, Turns fallback) {
  const auto field = owner.optional("fovy_deg");
  return field ? fovy(*field) : fallback;
}

AnimatedView read_keys(const JsonField& keys, std::uint32_t frame_count, Turns scene_fovy) {
  AnimatedView view;
  const auto elements = keys.elements();
  if (elements.empty()) keys.fail("expected an array of at least one key frame");
  for (const JsonField& key : elements) {
    key.expect_object_with_fields({"frame", "eye", "target", "up", "fovy_deg"});
    const JsonField frame = key.required("frame");
    const auto number = static_cast<std::uint32_t>(frame.integer(0, frame_count - 1, "a frame of the animation"));
    if (!view.keys.empty() && number <= view.keys.back().frame) {
      frame.fail("expected a frame after the previous key's " + std::to_string(view.keys.back().frame));
    }
    view.keys.push_back({number, {point(key.required("eye")), point(key.required("target")), point(key.required("up")),
                                  fovy_or(key, scene_fovy)}});
  }
  return view;
}

AnimatedView read_orbit(const JsonField& orbit, Turns scene_fovy) {
  orbit.expect_object_with_fields({"center", "radius", "start_deg", "turns", "target", "up", "fovy_deg"});
  AnimatedView view;
  fixedpoint::Orbit& o = view.orbit;
  o.center = point(orbit.required("center"));
  // The eye moves in x and z by up to the radius: keep it inside the range all the way round.
  const double room = coordinate_limit - std::ldexp(std::max(std::abs(o.center.x), std::abs(o.center.z)), -16) - std::ldexp(1.0, -16);
  const JsonField radius = orbit.required("radius");
  const double r = radius.number(detail::at_least(0.0));
  if (!(r <= room)) {
    radius.fail("expected a number in [0, " + detail::format_number(room) + "] (the orbit around center must stay within +-" +
                limit_text() + ")");
  }
  o.radius = fixedpoint::q16::from_double(r);
  if (const auto start = orbit.optional("start_deg")) o.start = fixedpoint::turns_from_degrees(start->number(detail::closed_interval(-360, 360)));
  o.turns = 1;
  if (const auto turns = orbit.optional("turns")) o.turns = static_cast<std::int32_t>(turns->integer(-max_turns, max_turns));
  o.target = point(orbit.required("target"));
  o.up = point(orbit.required("up"));
  o.fovy = fovy_or(orbit, scene_fovy);
  return view;
}

// Every frame's pose must be a view look_at builds: the firmware would get a status instead.
void require_valid_views(const AnimatedView& view, std::uint32_t frame_count, const std::string& file, const std::string& field) {
  for (std::uint32_t frame = 0; frame < frame_count; ++frame) {
    const ViewPose pose = fixedpoint::pose_at_frame(view.track(), frame, frame_count);
    const fixedpoint::PoseStatus status = fixedpoint::look_at(pose.eye, pose.target, pose.up).status;
    if (status != fixedpoint::PoseStatus::ok) {
      throw SceneError(file, field, "expected a valid view at every frame, got " + std::string(fixedpoint::pose_status_name(status)) +
                                        " at frame " + std::to_string(frame));
    }
  }
}

// A camera's or projector's track: its keys or its orbit, valid at every frame.
AnimatedView read_track(const JsonField& track, std::uint32_t frame_count, Turns scene_fovy) {
  track.expect_object_with_fields({"keys", "orbit"});
  const bool has_keys = track.has("keys"), has_orbit = track.has("orbit");
  if (has_keys && has_orbit) track.fail_member("orbit", "expected either keys or orbit, got both");
  if (!has_keys && !has_orbit) track.fail_with("expected an object with keys or orbit, got neither");
  const JsonField motion = track.required(has_keys ? "keys" : "orbit");
  const AnimatedView view = has_keys ? read_keys(motion, frame_count, scene_fovy) : read_orbit(motion, scene_fovy);
  require_valid_views(view, frame_count, motion.file().string(), motion.path());
  return view;
}

// The fovy a scene gives a view, in Turns: it must be inside perspective's range to be animated.
Turns scene_fovy(const Scene& scene, const std::string& field, double fovy_deg) {
  if (!(fovy_deg >= min_fovy_deg && fovy_deg <= max_fovy_deg)) {
    throw SceneError(scene.file.string(), field + ".fovy_deg",
                     "expected a number in [" + detail::format_number(min_fovy_deg) + ", " + detail::format_number(max_fovy_deg) +
                         "] to be animated, got " + detail::format_number(fovy_deg));
  }
  return fixedpoint::turns_from_degrees(fovy_deg);
}

// A view the animation leaves where the scene put it: the scene's pose, in the fixed-point formats.
AnimatedView still(const Scene& scene, const std::string& field, const glm::dvec3& eye, const glm::dvec3& target,
                   const glm::dvec3& up, double fovy_deg) {
  const auto to_point = [&](const glm::dvec3& v, const char* what) {
    if (!(std::abs(v.x) < coordinate_limit && std::abs(v.y) < coordinate_limit && std::abs(v.z) < coordinate_limit)) {
      throw SceneError(scene.file.string(), field + "." + what,
                       "expected coordinates in (-" + limit_text() + ", " + limit_text() + ") to be animated, got " + detail::format_vec3(v));
    }
    return fixedpoint::vec3_q16(v.x, v.y, v.z);
  };
  AnimatedView view;
  view.keys.push_back({0, {to_point(eye, "eye"), to_point(target, "target"), to_point(up, "up"), scene_fovy(scene, field, fovy_deg)}});
  const ViewPose& pose = view.keys[0].pose;
  const fixedpoint::PoseStatus status = fixedpoint::look_at(pose.eye, pose.target, pose.up).status;
  if (status != fixedpoint::PoseStatus::ok) {
    throw SceneError(scene.file.string(), field, "expected a view that stays valid rounded to 1/65536, got " +
                                                     std::string(fixedpoint::pose_status_name(status)));
  }
  return view;
}

std::size_t projector_named(const JsonField& track, const std::string& name, const Scene& scene) {
  std::string names;
  std::size_t found = scene.projectors.size(), count = 0;
  for (std::size_t i = 0; i < scene.projectors.size(); ++i) {
    names += (i ? ", " : "") + scene.projectors[i].name;
    if (scene.projectors[i].name == name) {
      found = i;
      ++count;
    }
  }
  if (count == 0) track.fail_with("expected the name of a projector of the scene (" + names + "), got " + name);
  if (count > 1) track.fail_with("expected the name of one projector, got a name " + std::to_string(count) + " projectors share");
  return found;
}

void read_version(const JsonField& root) {
  if (!root.has("spanlight_animation")) {
    root.fail_member("spanlight_animation", "expected the animation format version 1, got nothing: the field is missing");
  }
  const JsonField version = root.required("spanlight_animation");
  if (!version.json().is_number() || version.json().get<double>() != 1.0) version.fail("expected the animation format version 1");
}

}  // namespace

Animation load_animation(const std::filesystem::path& file, const Scene& scene) {
  const detail::Json document = detail::read_json_document(file, "animation file");
  const JsonField root(document, "", file);
  if (!document.is_object()) root.fail("expected a JSON object");
  read_version(root);
  root.expect_object_with_fields({"spanlight_animation", "frames", "camera", "projectors"});

  Animation animation;
  animation.file = file;
  animation.frame_count = static_cast<std::uint32_t>(root.required("frames").integer(1, fixedpoint::max_frame_count));
  const std::uint32_t count = animation.frame_count;

  const Camera& camera = scene.camera;
  if (const auto track = root.optional("camera")) {
    animation.camera = read_track(*track, count, scene_fovy(scene, "camera", camera.fovy_deg));
  } else {
    animation.camera = still(scene, "camera", camera.eye, camera.target, camera.up, camera.fovy_deg);
  }

  std::vector<bool> animated(scene.projectors.size(), false);
  animation.projectors.resize(scene.projectors.size());
  if (const auto projectors = root.optional("projectors")) {
    for (const auto& [name, track] : projectors->members()) {
      const std::size_t j = projector_named(track, name, scene);
      const std::string scene_field = "projectors[" + std::to_string(j) + "]";
      animation.projectors[j] = read_track(track, count, scene_fovy(scene, scene_field, scene.projectors[j].fovy_deg));
      animated[j] = true;
    }
  }
  for (std::size_t j = 0; j < scene.projectors.size(); ++j) {
    if (animated[j]) continue;
    const Projector& p = scene.projectors[j];
    const std::string field = "projectors[" + std::to_string(j) + "]";
    animation.projectors[j] = still(scene, field, p.eye, p.target, p.up, p.fovy_deg);
  }
  return animation;
}

}  // namespace spanlight::scene
