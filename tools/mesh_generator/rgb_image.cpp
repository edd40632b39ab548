#include "rgb_image.hpp"

#include <algorithm>
#include <cmath>

namespace spanlight::mesh_generator {

void RgbImage::set(int x, int y, glm::dvec3 colour) {
  const auto i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
  for (int c = 0; c < 3; ++c) {
    rgb[i + static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(colour[c], 0.0, 1.0)));
  }
}

double hash_unit(std::uint32_t a, std::uint32_t b, std::uint32_t seed) {
  // Chris Wellons' "lowbias32" finaliser over the three inputs folded together.
  std::uint32_t h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u ^ seed * 0xC2B2AE3Du;
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return h / 4294967296.0;
}

double tiling_value_noise(int x, int y, int size, int cells, std::uint32_t seed) {
  const int cell = size / cells;
  const int i = x / cell, j = y / cell;
  const auto lattice = [&](int a, int b) {
    return hash_unit(static_cast<std::uint32_t>(a % cells), static_cast<std::uint32_t>(b % cells), seed);
  };
  const auto smooth = [](double f) { return f * f * (3.0 - 2.0 * f); };  // zero slope at lattice points: no creases
  const double fx = smooth((x % cell + 0.5) / cell), fy = smooth((y % cell + 0.5) / cell);
  const double top = lattice(i, j) + (lattice(i + 1, j) - lattice(i, j)) * fx;
  const double bottom = lattice(i, j + 1) + (lattice(i + 1, j + 1) - lattice(i, j + 1)) * fx;
  return top + (bottom - top) * fy;
}

}  // namespace spanlight::mesh_generator
