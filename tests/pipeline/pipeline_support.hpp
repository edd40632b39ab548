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
#include "spanlight/render.hpp"

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

inline scene::Image solid_image(int width, int height, std::array<std::uint8_t, 3> rgb) {
  scene::Image image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width * height) * 3)};
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = rgb[i % 3];
  return image;
}

inline scene::Texture texture(std::string name, scene::Image image, scene::Filter filter, scene::Wrap wrap) {
  return scene::Texture{std::move(name), {}, filter, wrap, std::move(image)};
}

inline scene::Scene empty_scene(int width, int height, glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up,
                                double fovy_deg, double near, double far) {
  scene::Scene s;
  s.name = "ptest";
  s.file = "in-memory.json";
  s.width = width;
  s.height = height;
  s.camera = scene::Camera{eye, target, up, fovy_deg, near, far};
  return s;
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

inline scene::Projector projector(glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up, double fovy_deg, double near,
                                  double far, int image, glm::dvec3 color) {
  scene::Projector p;
  p.name = "projector";
  p.eye = eye;
  p.target = target;
  p.up = up;
  p.fovy_deg = fovy_deg;
  p.aspect = 1.0;
  p.near = near;
  p.far = far;
  p.image = image;
  p.color = color;
  return p;
}

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

// ---- fixed-pipeline frames with a pass observer --------------------------------

// Every touch of every pass, in order (passes.hpp: Observer::touched is static,
// so the log it writes to is a global the test installs around one render).
struct PassLog {
  std::vector<std::pair<int, std::int32_t>> events;
};

struct RecordingObserver {
  static inline PassLog* log = nullptr;
  static void touched(int pass, std::int32_t index) {
    if (log != nullptr) log->events.emplace_back(pass, index);
  }
};

struct ObservedFrame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;     // 8 bits a channel, top row first
  std::vector<std::uint32_t> depth;  // as stored
  PassLog log;
};

// render_frame with the recording observer, buffers set up as render_fixed does.
template <PixelFormat Format = PixelFormat::rgb888>
ObservedFrame render_observed(const PreparedScene& scene, const Precision& precision) {
  using F = HostFeatures<Format, 8, 1>;
  using Color = ColorTraits<Format>;
  const std::size_t pixels = std::size_t{scene.width} * scene.height;
  std::vector<typename Color::Storage> color(pixels * Color::per_pixel);
  ObservedFrame frame;
  frame.width = scene.width;
  frame.height = scene.height;
  frame.depth.resize(pixels);
  std::vector<std::vector<std::uint32_t>> maps(scene.projector_count);
  std::vector<std::uint32_t*> map_pointers(scene.projector_count, nullptr);
  for (std::size_t j = 0; j < scene.projector_count; ++j) {
    const ProjectorData& p = scene.projectors[j];
    if (!p.shadows) continue;
    maps[j].resize(std::size_t{p.map_size} * p.map_size);
    map_pointers[j] = maps[j].data();
  }
  std::vector<std::uint8_t> tie_mask(tie_mask_bytes(scene.width, scene.height));
  const FrameTarget<Format, std::uint32_t> target{color.data(), frame.depth.data(), map_pointers.data(),
                                                  tie_mask.data()};
  RecordingObserver::log = &frame.log;
  const RenderStatus status = render_frame<F, std::uint32_t, RecordingObserver>(scene, target, precision);
  RecordingObserver::log = nullptr;
  if (status != RenderStatus::ok) throw std::runtime_error("render_frame refused the frame");
  frame.rgb.resize(pixels * 3);
  for (std::size_t i = 0; i < pixels; ++i) {
    const Rgb8 c = Color::load(color.data() + i * Color::per_pixel);
    frame.rgb[i * 3] = c.r;
    frame.rgb[i * 3 + 1] = c.g;
    frame.rgb[i * 3 + 2] = c.b;
  }
  return frame;
}

// Counts every pixel() call of a draw: no depth test, so a pixel two
// triangles both cover is counted twice.
struct CountingKernel {
  std::vector<int>* counts;
  SpanNeeds needs() const { return {false, 0, 0}; }
  void object(const ObjectData&) {}
  template <typename V>
  void pixel(std::int32_t i, const V&) {
    ++(*counts)[static_cast<std::size_t>(i)];
  }
};

// How many times the eye pass's geometry walk covers each pixel.
inline std::vector<int> eye_coverage_counts(const PreparedScene& scene) {
  using F = HostFeatures<PixelFormat::rgb888, 8, 1>;
  std::vector<int> counts(std::size_t{scene.width} * scene.height, 0);
  CountingKernel kernel{&counts};
  draw_pass<F>(scene, PassView{scene.width, scene.height, -1}, Precision{}, kernel);
  return counts;
}

// The snapped window position the pipeline gives a vertex of an object in the eye pass.
inline ScreenVertex pipeline_screen_vertex(const PreparedScene& scene, const ObjectData& object, std::uint32_t index) {
  return project(transform(object.clip_from_object, object.positions + index * 3), scene.width, scene.height);
}

}  // namespace spanlight::ptest
