// Scene pieces the pipeline and extremes tests both build in memory. Each
// suite's own support header re-exports them into its namespace.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace spanlight::test_support {

inline scene::Image solid_image(int width, int height, std::array<std::uint8_t, 3> rgb) {
  scene::Image image{width, height,
                     std::vector<std::uint8_t>(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3)};
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = rgb[i % 3];
  return image;
}

inline scene::Texture texture(std::string name, scene::Image image, scene::Filter filter, scene::Wrap wrap) {
  return scene::Texture{std::move(name), {}, filter, wrap, std::move(image)};
}

// A scene with nothing in it yet, as if read from "in-memory.json"; the camera
// looks from `eye` at `target`.
inline scene::Scene empty_scene(std::string name, int width, int height, glm::dvec3 eye, glm::dvec3 target,
                                glm::dvec3 up, double fovy_deg, double near, double far) {
  scene::Scene s;
  s.name = std::move(name);
  s.file = "in-memory.json";
  s.width = width;
  s.height = height;
  s.camera = scene::Camera{eye, target, up, fovy_deg, near, far};
  return s;
}

// A square-aspect projector named "projector" showing textures[image].
inline scene::Projector projector(glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up, double fovy_deg, double near,
                                  double far, int image, glm::dvec3 color = glm::dvec3(1.0)) {
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

}  // namespace spanlight::test_support
