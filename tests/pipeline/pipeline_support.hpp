// Shared helpers for the fixed pipeline's tests: the shared scenes, scenes
// built in memory, a pass observer that records every pixel a pass touches,
// and a kernel that counts every covered pixel of a draw (with no depth test).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "prepare/prepare.hpp"
#include "prepare/render_fixed.hpp"
#include "scene/scene.hpp"
#include "eye_pass.hpp"
#include "spanlight/render.hpp"
#include "../support/scene_builders.hpp"

// The sanitizer twin runs the same properties on fewer random cases.
#if defined(__SANITIZE_ADDRESS__)
#define SPANLIGHT_PTEST_SANITIZED 1
#else
#define SPANLIGHT_PTEST_SANITIZED 0
#endif

namespace spanlight::ptest {

inline constexpr bool sanitized = SPANLIGHT_PTEST_SANITIZED != 0;

// ---- the shared scenes -----------------------------------------------------

inline std::filesystem::path scene_file(const std::string& name) {
  return std::filesystem::path(SPANLIGHT_SOURCE_DIR) / "scenes" / (name + ".json");
}

inline const std::array<const char*, 4>& shared_scene_names() {
  static const std::array<const char*, 4> names{"horizon", "slide_projector", "spot_shadow", "three_projectors"};
  return names;
}

// ---- scenes built in memory --------------------------------------------------

using test_support::solid_image;
using test_support::texture;

inline scene::Scene empty_scene(int width, int height, glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up,
                                double fovy_deg, double near, double far) {
  return test_support::empty_scene("ptest", width, height, eye, target, up, fovy_deg, near, far);
}

// A quad a, b, c, d as triangles (a, b, c) and (a, c, d); uv 0.
inline scene::Object quad(std::string name, std::array<glm::dvec3, 4> corners, glm::dvec3 color = glm::dvec3(1.0)) {
  scene::Object object;
  object.name = std::move(name);
  object.mesh.positions.assign(corners.begin(), corners.end());
  object.mesh.uvs.assign(4, glm::dvec2(0.0));
  object.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  object.color = color;
  return object;
}

using test_support::projector;

// A floor (y = 0, |x| <= 6, -8 <= z <= 6, white) that the plane q = 0 cuts
// through: the projector's eye lies on the floor at (0, 0, 0.5) and looks 9.7
// degrees down, so the lit region is a wedge whose apex is the eye, on the
// q = 0 line, and the camera (from (0, 6, 7)) sees the wedge and a wide band
// of floor behind the projector (q < 0). Ambient 0.2, projector colour 0.5,
// white 256x256 image with nearest filtering.
inline scene::Scene apex_floor_scene() {
  auto s = empty_scene(200, 150, {0, 6, 7}, {0, 0, -1}, {0, 1, 0}, 60.0, 0.1, 40.0);
  s.ambient = glm::dvec3(0.2);
  s.textures.push_back(texture("white", solid_image(256, 256, {255, 255, 255}), scene::Filter::nearest,
                               scene::Wrap::clamp));
  s.objects.push_back(quad("floor", {glm::dvec3(-6, 0, 6), glm::dvec3(6, 0, 6), glm::dvec3(6, 0, -8),
                                     glm::dvec3(-6, 0, -8)}));
  s.projectors.push_back(projector({0, 0, 0.5}, {0, -0.6, -3.0}, {0, 1, 0}, 50.0, 0.05, 30.0, 0, glm::dvec3(0.5)));
  return s;
}
inline constexpr double apex_floor_half_x = 6.0, apex_floor_z_min = -8.0, apex_floor_z_max = 6.0;

// ---- eye rays: where a pixel centre lands on a plane, in double ---------------

struct Ray {
  glm::dvec3 origin, direction;
};

// The eye ray through the centre of pixel (px, py) (y down), from the scene's own matrices.
inline Ray pixel_ray(const scene::Scene& s, double px, double py) {
  const glm::dmat4 inverse = glm::inverse(scene::camera_view_projection(s));
  const double x_ndc = (px + 0.5) / s.width * 2.0 - 1.0;
  const double y_ndc = 1.0 - (py + 0.5) / s.height * 2.0;
  const glm::dvec4 a = inverse * glm::dvec4(x_ndc, y_ndc, -1.0, 1.0);
  const glm::dvec4 b = inverse * glm::dvec4(x_ndc, y_ndc, 1.0, 1.0);
  const glm::dvec3 near_point = glm::dvec3(a) / a.w, far_point = glm::dvec3(b) / b.w;
  return {near_point, far_point - near_point};
}

// The point where the ray meets the plane y = height (parameter > 0), or false.
inline bool hit_plane_y(const Ray& ray, double height, glm::dvec3& hit) {
  if (std::fabs(ray.direction.y) < 1e-300) return false;
  const double t = (height - ray.origin.y) / ray.direction.y;
  if (!(t > 0.0)) return false;
  hit = ray.origin + t * ray.direction;
  return true;
}

// ---- fixed-pipeline frames with a pass log --------------------------------------

// Every touch of every pass, in order, with the projector of a light pass (else -1).
struct PassEvent {
  Pass pass;
  int projector;
  std::uint32_t index;
};
struct PassLog {
  std::vector<PassEvent> events;
};

struct RecordingHooks : NoHooks {
  PassLog* log;
  int projector = -1;
  void pass_begin(Pass, int j) { projector = j; }
  void touched(Pass pass, std::uint32_t index) { log->events.push_back({pass, projector, index}); }
};

struct ObservedFrame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;     // 8 bits a channel, top row first
  std::vector<std::uint32_t> depth;  // as stored
  PassLog log;
};

// render_frame with the recording hooks, buffers set up as render_fixed does.
inline ObservedFrame render_observed(const prepare::PreparedStorage& prepared, const Knobs& knobs) {
  ObservedFrame frame;
  RecordingHooks hooks{};
  hooks.log = &frame.log;
  const prepare::FixedFrame fixed = prepare::render_fixed_with_hooks(prepared, knobs, hooks);
  frame.width = fixed.width;
  frame.height = fixed.height;
  frame.rgb = fixed.rgb;
  frame.depth = fixed.depth;
  return frame;
}

inline Knobs knobs_with(Passes passes, std::uint8_t depth_bits = 24, PixelFormat format = PixelFormat::rgb888) {
  Knobs k;
  k.passes = passes;
  k.depth_bits = depth_bits;
  k.format = format;
  return k;
}

}  // namespace spanlight::ptest
