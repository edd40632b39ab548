#include "terrain.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace spanlight::mesh_generator {

namespace {

constexpr int columns = 48, rows = 32;             // cells along x and z
constexpr double width = 3.0, depth = 2.0;          // x in [-1.5, 1.5], z in [-1, 1]
constexpr double texture_repeats_per_unit = 4.0 / 3.0;

double height(double x, double z) {
  const double r2 = (x / 1.5) * (x / 1.5) + z * z;
  const double hill = std::pow(std::max(0.0, 1.0 - r2), 2.0);
  const double ridges = 0.06 * std::sin(5.0 * x + 1.0) * std::cos(4.0 * z) + 0.04 * std::sin(9.0 * x - 7.0 * z);
  return 0.55 * hill + ridges * (0.3 + hill);
}

}  // namespace

IndexedMesh terrain() {
  IndexedMesh mesh;
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= columns; ++i) {
      const double x = width * (static_cast<double>(i) / columns - 0.5);
      const double z = depth * (static_cast<double>(j) / rows - 0.5);
      mesh.positions.push_back({x, height(x, z), z});
      mesh.uvs.push_back({(x + width / 2) * texture_repeats_per_unit, (depth / 2 - z) * texture_repeats_per_unit});
    }
  }
  const auto at = [](int i, int j) {
    const auto index = static_cast<std::uint32_t>(j * (columns + 1) + i);
    return Corner{index, index};  // no seams: one uv per position
  };
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      // a, b along +x, d below a along +z; counter-clockwise seen from above. The diagonal
      // alternates like a checkerboard, so the surface has no grain in one direction.
      const Corner a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if ((i + j) % 2 == 0) {
        mesh.faces.push_back({a, d, c});
        mesh.faces.push_back({a, c, b});
      } else {
        mesh.faces.push_back({a, d, b});
        mesh.faces.push_back({b, d, c});
      }
    }
  }
  return mesh;
}

}  // namespace spanlight::mesh_generator
