#include "test_pattern.hpp"

namespace spanlight::selftest {
namespace {

std::uint8_t channel(std::uint32_t value) { return static_cast<std::uint8_t>(value & 0xFFu); }

}  // namespace

void fill_test_pattern(std::span<std::uint8_t> rgb, hal::FrameSize size) {
  const std::uint32_t width = size.width;
  const std::uint32_t height = size.height;
  const std::int32_t centre_x = static_cast<std::int32_t>(width / 2);
  const std::int32_t centre_y = static_cast<std::int32_t>(height / 2);
  std::size_t i = 0;
  for (std::uint32_t y = 0; y < height; ++y) {
    const std::int32_t dy = static_cast<std::int32_t>(y) - centre_y;
    for (std::uint32_t x = 0; x < width; ++x) {
      const std::int32_t dx = static_cast<std::int32_t>(x) - centre_x;
      // Ramps use a real division on purpose: the M0+ has no divide instruction, so this
      // checks libgcc's __aeabi_uidiv gives the host's answer.
      const std::uint32_t red = x * 255u / (width - 1u);
      const std::uint32_t green = y * 255u / (height - 1u);
      const std::uint32_t rings = static_cast<std::uint32_t>(dx * dx + dy * dy) >> 5;
      const std::uint32_t checker = ((x >> 4) ^ (y >> 4)) & 1u ? 0x40u : 0u;
      rgb[i++] = channel(red ^ (checker >> 1));
      rgb[i++] = channel(green + (rings & 0x1Fu));
      rgb[i++] = channel(rings + checker);
    }
  }
}

std::uint32_t fnv1a(std::span<const std::uint8_t> bytes) {
  std::uint32_t hash = 2166136261u;
  for (const std::uint8_t byte : bytes) {
    hash = (hash ^ byte) * 16777619u;
  }
  return hash;
}

}  // namespace spanlight::selftest
