#include "scene/mip_chain.hpp"

#include <bit>
#include <stdexcept>
#include <string>

namespace spanlight::scene {
namespace {

bool is_power_of_two(int size) { return size > 0 && std::has_single_bit(static_cast<unsigned>(size)); }

}  // namespace

Image half_level(const Image& level) {
  const int sx = level.width > 1 ? 2 : 1;  // texels of `level` per texel of the next, along x
  const int sy = level.height > 1 ? 2 : 1;
  Image next;
  next.width = level.width / sx;
  next.height = level.height / sy;
  next.rgb.resize(static_cast<std::size_t>(next.width) * static_cast<std::size_t>(next.height) * 3);
  const unsigned count = static_cast<unsigned>(sx * sy);
  for (int y = 0; y < next.height; ++y) {
    for (int x = 0; x < next.width; ++x) {
      for (std::size_t c = 0; c < 3; ++c) {
        unsigned sum = 0;
        for (int dy = 0; dy < sy; ++dy)
          for (int dx = 0; dx < sx; ++dx) sum += level.texel(x * sx + dx, y * sy + dy)[c];
        // Rounded half up: floor(sum / count + 1/2).
        const auto i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(next.width) + static_cast<std::size_t>(x)) * 3 + c;
        next.rgb[i] = static_cast<std::uint8_t>((sum + count / 2) / count);
      }
    }
  }
  return next;
}

std::vector<Image> mip_chain(const Image& image) {
  if (!is_power_of_two(image.width) || !is_power_of_two(image.height)) {
    throw std::invalid_argument("mip_chain: a " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                                " image; mipmaps need power-of-two sides");
  }
  std::vector<Image> chain{image};
  while (chain.back().width > 1 || chain.back().height > 1) chain.push_back(half_level(chain.back()));
  return chain;
}

std::size_t mip_chain_texels(int width, int height) {
  if (!is_power_of_two(width) || !is_power_of_two(height)) throw std::invalid_argument("mip_chain_texels: sides must be powers of two");
  std::size_t texels = 0;
  for (;;) {
    texels += static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    if (width == 1 && height == 1) return texels;
    width = width > 1 ? width / 2 : 1;
    height = height > 1 ? height / 2 : 1;
  }
}

}  // namespace spanlight::scene
