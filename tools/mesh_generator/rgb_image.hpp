// An 8-bit RGB image, top row first (what the scene loader reads), and the
// integer noise the textures are made of. Textures use only integer hashing,
// + - * / and sqrt (all exactly rounded in IEEE double), never sin, cos or pow:
// the same bytes on every machine, so the committed PNGs can be compared exactly.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace spanlight::mesh_generator {

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3

  RgbImage(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3) {}
  // colour in [0, 1] per channel (clamped), stored as round(255 * c).
  void set(int x, int y, glm::dvec3 colour);
};

// A well-mixed 32-bit hash of three integers, as a number in [0, 1).
double hash_unit(std::uint32_t a, std::uint32_t b, std::uint32_t seed);

// Smooth value noise in [0, 1] at texel (x, y), from a lattice of `cells` x `cells`
// random values over a `size`-texel square; repeats every `size` texels (cells divides size).
double tiling_value_noise(int x, int y, int size, int cells, std::uint32_t seed);

}  // namespace spanlight::mesh_generator
