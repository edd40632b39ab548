// Emits a baked animation (bake --animation): the SceneAnimation the firmware plays
// with scene_pose_at_frame, as constants (key frames or an orbit per view, the
// frustums in their fixed-point formats, each object's model matrix).
#include <sstream>

#include "bake/bake.hpp"

namespace spanlight::bake {
namespace {

void write_point(std::ostream& out, const fixedpoint::Vec3Q16& p) { out << "{" << p.x << ", " << p.y << ", " << p.z << "}"; }

void write_turns(std::ostream& out, fixedpoint::Turns t) { out << "fixedpoint::Turns{" << t.raw << "u}"; }

void write_pose(std::ostream& out, const fixedpoint::ViewPose& p) {
  out << "{";
  write_point(out, p.eye);
  out << ", ";
  write_point(out, p.target);
  out << ", ";
  write_point(out, p.up);
  out << ", ";
  write_turns(out, p.fovy);
  out << "}";
}

// The key frames of one view (when it has any) as an array named `name`.
void write_keys(std::ostream& out, const std::string& name, const scene::AnimatedView& view) {
  if (view.keys.empty()) return;
  out << "const fixedpoint::KeyFrame " << name << "[" << view.keys.size() << "] = {\n";
  for (const fixedpoint::KeyFrame& k : view.keys) {
    out << "  {" << k.frame << ", ";
    write_pose(out, k.pose);
    out << "},\n";
  }
  out << "};\n";
}

void write_animated(std::ostream& out, const std::string& keys_name, const scene::AnimatedView& view, const AnimatedCamera& c) {
  const fixedpoint::Orbit& o = view.orbit;
  out << "{{" << (view.keys.empty() ? "nullptr" : keys_name) << ", " << view.keys.size() << ", {";
  write_point(out, o.center);
  out << ", fixedpoint::q16::from_raw(" << o.radius.raw() << "), ";
  write_turns(out, o.start);
  out << ", " << o.turns << ", ";
  write_point(out, o.target);
  out << ", ";
  write_point(out, o.up);
  out << ", ";
  write_turns(out, o.fovy);
  out << "}}, {" << c.aspect.width << "u, " << c.aspect.height << "u}, fixedpoint::q16::from_raw(" << c.near.raw()
      << "), fixedpoint::q16::from_raw(" << c.far.raw() << ")}";
}

}  // namespace

std::string baked_animation_config(const prepare::PreparedAnimation& a) {
  std::ostringstream out;
  out << "\n// The animation baked with --animation " << a.source.file.filename().string() << " (docs/live-scenes.md):\n"
      << "// scene_pose_at_frame(animation, k, projector_storage) is frame k's pose.\n"
      << "inline constexpr std::uint32_t frame_count = " << a.animation.frame_count << ";\n"
      << "inline constexpr std::uint16_t object_count = " << a.animation.object_count << ";\n"
      << "extern const spanlight::SceneAnimation animation;\n";
  return out.str();
}

std::string baked_animation_source(const prepare::PreparedAnimation& a) {
  const SceneAnimation& s = a.animation;
  std::ostringstream out;
  out << "\n// The animation: " << a.source.file.filename().string() << "\nnamespace {\n\n";
  write_keys(out, "camera_keys", a.source.camera);
  for (std::size_t j = 0; j < a.source.projectors.size(); ++j)
    write_keys(out, "projector_keys_" + std::to_string(j), a.source.projectors[j]);
  out << "const AnimatedCamera animated_projectors[" << (s.projector_count ? s.projector_count : 1) << "] = {\n";
  for (std::size_t j = 0; j < a.source.projectors.size(); ++j) {
    out << "  ";
    write_animated(out, "projector_keys_" + std::to_string(j), a.source.projectors[j], a.projectors[j]);
    out << ",\n";
  }
  if (s.projector_count == 0) out << "  {},\n";
  out << "};\nconst Mat4Block models[" << (s.object_count ? s.object_count : 1) << "] = {\n";
  for (const Mat4Block& m : a.models) {
    out << "  {{";
    for (int i = 0; i < 16; ++i) out << m.m[i] << (i < 15 ? ", " : "");
    out << "}, " << m.frac_bits << "},\n";
  }
  if (s.object_count == 0) out << "  {},\n";
  out << "};\n\n}  // namespace\n\nconst SceneAnimation animation{" << s.frame_count << ", ";
  write_animated(out, "camera_keys", a.source.camera, s.camera);
  out << ", animated_projectors, " << int(s.projector_count) << ", models, " << s.object_count << "};\n";
  return out.str();
}

}  // namespace spanlight::bake
