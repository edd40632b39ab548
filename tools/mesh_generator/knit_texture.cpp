#include <array>
#include <cmath>

#include "textures.hpp"

namespace spanlight::mesh_generator {

namespace {

constexpr int size = 256;
constexpr int stitch = 8;  // texels a stitch is wide and tall: 32 x 32 stitches

// Stitch rows of one repeat (32), honey with a cream-red-cream band and a brown one.
glm::dvec3 band_colour(int row) {
  const glm::dvec3 honey{0.78, 0.55, 0.30}, cream{0.93, 0.88, 0.75}, berry{0.70, 0.18, 0.20}, brown{0.40, 0.25, 0.15};
  if (row == 10 || row == 11 || row == 14 || row == 15) return cream;
  if (row == 12 || row == 13) return berry;
  if (row == 26 || row == 27) return brown;
  return honey;
}

// How far inside one leg of the stitch's V the texel centre is: 0 on its outline, 1 on its
// middle line, negative outside. The leg is an ellipse leaning out toward the top of the cell.
double leg_depth(double x, double y) {
  const double centre_x = 2.3, centre_y = 4.0;     // left leg; the right one is its mirror image
  const double lean_x = -0.41, lean_y = -0.912;    // unit vector up the leg (image rows grow downward)
  const double half_length = 4.6, half_width = 1.9;
  const double dx = x - centre_x, dy = y - centre_y;
  const double along = (dx * lean_x + dy * lean_y) / half_length;
  const double across = (dx * lean_y - dy * lean_x) / half_width;
  return 1.0 - (along * along + across * across);
}

}  // namespace

RgbImage knit_texture() {
  RgbImage image(size, size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const int column = x / stitch, row = y / stitch;
      const double cx = x % stitch + 0.5, cy = y % stitch + 0.5;
      const double depth = std::max(leg_depth(cx, cy), leg_depth(stitch - cx, cy));
      // Yarn is brightest along a leg's middle and dark in the gaps between legs.
      const double shade = depth > 0.0 ? 0.55 + 0.45 * std::sqrt(depth) : 0.35;
      const double stitch_variation = 0.92 + 0.16 * hash_unit(static_cast<std::uint32_t>(column), static_cast<std::uint32_t>(row), 1);
      const double fuzz = 0.95 + 0.10 * hash_unit(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y), 2);
      image.set(x, y, band_colour(row) * (shade * stitch_variation * fuzz));
    }
  }
  return image;
}

}  // namespace spanlight::mesh_generator
