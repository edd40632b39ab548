// Hand-made scenes whose pictures are known. Most look head-on at the plane z = 0:
// a 64 x 64 picture from (0, 0, 4) with fovy 90, where the plane's point (x, y) lands at
// pixel position (32 + 8x, 32 - 8y). Rectangles with corners at multiples of 1/8 unit
// have their corners on whole pixels, on the 1/256-pixel grid, so snapping moves nothing,
// pixel centres never lie on an edge, and the expected picture holds to double rounding.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace spanlight::effects {

inline constexpr int side = 64;           // pixels
inline constexpr double pixels_per_unit = 8.0;

inline scene::Scene head_on_scene() {
  scene::Scene s;
  s.name = "effect";
  s.version = 2;
  s.width = side;
  s.height = side;
  s.camera = scene::Camera{{0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 90.0, 0.5, 40.0};
  return s;
}

// The point of the plane z = 0 seen at the centre of pixel (px, py) by head_on_scene's camera.
inline glm::dvec2 plane_point(int px, int py) {
  return {(px + 0.5 - side / 2) / pixels_per_unit, (side / 2 - (py + 0.5)) / pixels_per_unit};
}

// Is pixel (px, py) inside the rectangle [x0, x1] x [y0, y1] of the plane (corners on whole pixels)?
inline bool inside(int px, int py, double x0, double y0, double x1, double y1) {
  const glm::dvec2 p = plane_point(px, py);
  return p.x > x0 && p.x < x1 && p.y > y0 && p.y < y1;
}

// An axis-aligned rectangle in the plane z, counter-clockwise seen from +z, uv 0..1.
inline scene::Object rectangle(std::string name, double x0, double y0, double x1, double y1, double z = 0.0) {
  scene::Object o;
  o.name = std::move(name);
  o.mesh.positions = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}};
  o.mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  o.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return o;
}

inline scene::Image grey_image(int width, int height, const std::vector<int>& values) {
  scene::Image image{width, height, {}};
  for (const int v : values) image.rgb.insert(image.rgb.end(), 3, static_cast<std::uint8_t>(v));
  return image;
}

inline int add_texture(scene::Scene& s, std::string name, scene::Image image, scene::Filter filter, scene::Wrap wrap) {
  s.textures.push_back(scene::Texture{std::move(name), {}, filter, wrap, std::move(image)});
  return static_cast<int>(s.textures.size()) - 1;
}

inline scene::Projector projector(glm::dvec3 eye, glm::dvec3 target, double fovy_deg, double near, double far, int image,
                                  glm::dvec3 color = glm::dvec3(1.0)) {
  scene::Projector p;
  p.name = "projector";
  p.eye = eye;
  p.target = target;
  p.up = {0, 1, 0};
  p.fovy_deg = fovy_deg;
  p.near = near;
  p.far = far;
  p.image = image;
  p.color = color;
  return p;
}

// round(255 * value), the byte a renderer writes for an exact value.
inline int byte_of(double value) { return static_cast<int>(std::lround(255.0 * value)); }

}  // namespace spanlight::effects
