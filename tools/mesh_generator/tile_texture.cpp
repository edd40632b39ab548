#include <array>

#include "textures.hpp"

namespace spanlight::mesh_generator {

namespace {

constexpr int size = 128;
constexpr int tile = 16;   // texels per tile, grout included: 8 x 8 tiles
constexpr int grout = 2;   // the last two rows and columns of each tile
constexpr int bevel = 2;   // glaze highlight along the top and left edges, shadow along the others

}  // namespace

RgbImage tile_texture() {
  const std::array<glm::dvec3, 4> glazes{{{0.20, 0.45, 0.70}, {0.25, 0.60, 0.62}, {0.86, 0.85, 0.80}, {0.14, 0.28, 0.52}}};
  const glm::dvec3 grout_colour{0.55, 0.52, 0.48};
  RgbImage image(size, size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const int tx = x % tile, ty = y % tile;
      const double fuzz = 0.94 + 0.12 * hash_unit(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 3);
      if (tx >= tile - grout || ty >= tile - grout) {
        image.set(x, y, grout_colour * fuzz);
        continue;
      }
      const double pick = hash_unit(static_cast<std::uint32_t>(x / tile), static_cast<std::uint32_t>(y / tile), 4);
      const glm::dvec3 glaze = glazes[static_cast<std::size_t>(pick * glazes.size())];
      const int inner = tile - grout;
      const double edge = (tx < bevel || ty < bevel) ? 1.25 : (tx >= inner - bevel || ty >= inner - bevel) ? 0.75 : 1.0;
      image.set(x, y, glaze * (edge * fuzz));
    }
  }
  return image;
}

}  // namespace spanlight::mesh_generator
