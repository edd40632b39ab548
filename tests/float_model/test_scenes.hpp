// Scenes and images built in code for the float model tests: small enough to
// work out by hand what every pixel must show.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace spanlight::test {

// An image whose texels are all `rgb`.
inline scene::Image solid_image(int width, int height, std::array<std::uint8_t, 3> rgb) {
  scene::Image image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width * height) * 3)};
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = rgb[i % 3];
  return image;
}

// Black and white squares, one texel each; texel (0, 0) (top-left in the file) is white.
inline scene::Image checker_image(int size) {
  scene::Image image{size, size, {}};
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const std::uint8_t v = (x + y) % 2 == 0 ? 255 : 0;
      image.rgb.insert(image.rgb.end(), {v, v, v});
    }
  }
  return image;
}

inline scene::Texture texture(std::string name, scene::Image image, scene::Filter filter, scene::Wrap wrap) {
  return scene::Texture{std::move(name), {}, filter, wrap, std::move(image)};
}

// A quad a, b, c, d (counter-clockwise seen from its front) as two triangles.
inline scene::Object quad(std::string name, std::array<glm::dvec3, 4> corners,
                          std::array<glm::dvec2, 4> uvs = {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1),
                                                           glm::dvec2(0, 1)}) {
  scene::Object object;
  object.name = std::move(name);
  object.mesh.positions.assign(corners.begin(), corners.end());
  object.mesh.uvs.assign(uvs.begin(), uvs.end());
  object.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return object;
}

// A scene with nothing in it yet; the camera looks from `eye` at `target`.
inline scene::Scene empty_scene(int width, int height, glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up,
                                double fovy_deg, double near, double far) {
  scene::Scene s;
  s.name = "test";
  s.width = width;
  s.height = height;
  s.camera = scene::Camera{eye, target, up, fovy_deg, near, far};
  return s;
}

// A fresh, empty folder under the system's temporary folder, private to this
// process (ctest runs the plain and the sanitizer build of a test side by side).
inline std::filesystem::path fresh_folder(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() /
                      ("spanlight_float_model_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

}  // namespace spanlight::test
