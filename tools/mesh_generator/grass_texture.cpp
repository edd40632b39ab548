#include <algorithm>

#include "textures.hpp"

namespace spanlight::mesh_generator {

namespace {

constexpr int size = 128;

}  // namespace

RgbImage grass_texture() {
  const glm::dvec3 grass{0.28, 0.50, 0.17}, dry{0.62, 0.55, 0.32}, soil{0.36, 0.27, 0.18};
  RgbImage image(size, size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      // Three octaves of tiling noise: large dry patches, smaller tufts, single blades.
      const double patches = tiling_value_noise(x, y, size, 4, 5);
      const double tufts = tiling_value_noise(x, y, size, 16, 6);
      const double blades = hash_unit(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 7);
      const double dryness = std::clamp((patches - 0.45) * 2.5 + (tufts - 0.5) * 0.6, 0.0, 1.0);
      const glm::dvec3 base = grass + (dry - grass) * dryness;
      const glm::dvec3 colour = blades < 0.08 ? soil : base * (0.85 + 0.3 * blades);
      image.set(x, y, colour);
    }
  }
  return image;
}

}  // namespace spanlight::mesh_generator
