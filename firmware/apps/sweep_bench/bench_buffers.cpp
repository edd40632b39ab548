// Every buffer is static and sized at compile time from the baked scene: no heap.
#include <array>

#include "bench_features.hpp"

namespace bench {
namespace {

constexpr std::uint32_t pixel_count = std::uint32_t{baked::width} * baked::height;
constexpr int map_slots = baked::projector_count ? baked::projector_count : 1;

std::array<Color::Storage, pixel_count * Color::per_pixel> color;
std::array<Depth, pixel_count> depth;
std::array<Depth, baked::shadow_map_texels ? baked::shadow_map_texels : 1> shadow_pool;
std::array<std::uint8_t, spanlight::tie_mask_bytes(baked::width, baked::height)> tie_mask;
std::array<Depth*, map_slots> maps;

}  // namespace

Target frame_target() {
  std::uint32_t offset = 0;
  for (int j = 0; j < baked::projector_count; ++j) {
    const std::uint32_t size = baked::shadow_map_size[j];
    maps[static_cast<std::size_t>(j)] = size ? shadow_pool.data() + offset : nullptr;
    offset += size * size;
  }
  return {color.data(), depth.data(), maps.data(), tie_mask.data()};
}

std::uint32_t frame_hash() {
  std::uint32_t h = 2166136261u;
  for (const Color::Storage value : color) {
    for (std::size_t b = 0; b < sizeof(Color::Storage); ++b) {
      h ^= static_cast<std::uint8_t>(static_cast<std::uint32_t>(value) >> (8 * b));
      h *= 16777619u;
    }
  }
  return h;
}

}  // namespace bench
