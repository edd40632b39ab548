// Colour at a pixel: 8-bit levels in registers, the framebuffer's format in
// memory. Light and surface are combined in 8-bit levels, every step rounded
// to nearest, as the paper's passes do in an 8-bit framebuffer:
//   light   = min(255, ambient + sum of each projector's light)   (quantised to the format after each add)
//   pixel   = round(light * surface / 255)
#pragma once

#include <cstdint>

#include "spanlight/knobs.hpp"

namespace spanlight {

// A colour packed in one register as 0x00RRGGBB (the texel layout too).
using Rgb = std::uint32_t;

[[gnu::always_inline]] constexpr std::uint32_t red(Rgb c) { return (c >> 16) & 255u; }
[[gnu::always_inline]] constexpr std::uint32_t green(Rgb c) { return (c >> 8) & 255u; }
[[gnu::always_inline]] constexpr std::uint32_t blue(Rgb c) { return c & 255u; }
[[gnu::always_inline]] constexpr Rgb rgb(std::uint32_t r, std::uint32_t g, std::uint32_t b) { return (r << 16) | (g << 8) | b; }

// round(a * b / 255) for a, b in [0, 255], exact (Blinn's trick).
[[gnu::always_inline]] constexpr std::uint32_t mul255(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t t = a * b + 128u;
  return (t + (t >> 8)) >> 8;
}

// light * surface per channel, mul255's rounding run on red and blue at once in
// two 16-bit lanes (each lane's t = a * b + 128 < 2^16, so the lanes never meet).
[[gnu::always_inline]] constexpr Rgb modulate(Rgb light, Rgb surface) {
  constexpr std::uint32_t lanes = 0x00FF00FFu;
  const std::uint32_t t = ((red(light) * red(surface) + 128u) << 16) | (blue(light) * blue(surface) + 128u);
  const std::uint32_t rb = ((t + ((t >> 8) & lanes)) >> 8) & lanes;
  return rb | (mul255(green(light), green(surface)) << 8);
}

[[gnu::always_inline]] constexpr Rgb add_light(Rgb base, Rgb light) {
  auto add = [](std::uint32_t a, std::uint32_t b) { return a + b > 255u ? 255u : a + b; };
  return rgb(add(red(base), red(light)), add(green(base), green(light)), add(blue(base), blue(light)));
}

// ---- framebuffer formats ------------------------------------------------------

template <PixelFormat Format>
struct ColorTraits;

template <>
struct ColorTraits<PixelFormat::rgb888> {
  using Storage = std::uint8_t;
  static constexpr int per_pixel = 3;  // R, G, B bytes
  [[gnu::always_inline]] static Rgb load(const Storage* p) { return rgb(p[0], p[1], p[2]); }
  [[gnu::always_inline]] static void store(Storage* p, Rgb c) {
    p[0] = static_cast<std::uint8_t>(c >> 16);
    p[1] = static_cast<std::uint8_t>(c >> 8);
    p[2] = static_cast<std::uint8_t>(c);
  }
  [[gnu::always_inline]] static constexpr Rgb quantize(Rgb c) { return c; }
};

// round(c * 31 / 255) and round(c * 63 / 255) without a divide (exact for c in [0, 255]).
[[gnu::always_inline]] constexpr std::uint32_t to5(std::uint32_t c) { return (c * 249u + 1014u) >> 11; }
[[gnu::always_inline]] constexpr std::uint32_t to6(std::uint32_t c) { return (c * 253u + 505u) >> 10; }
[[gnu::always_inline]] constexpr std::uint32_t from5(std::uint32_t c) { return (c << 3) | (c >> 2); }
[[gnu::always_inline]] constexpr std::uint32_t from6(std::uint32_t c) { return (c << 2) | (c >> 4); }

// 0x00RRGGBB to RGB565: red and blue rounded together in two 16-bit lanes
// (255 * 249 + 1014 < 2^16, so a lane's product never reaches the next).
[[gnu::always_inline]] constexpr std::uint32_t pack565(Rgb c) {
  const std::uint32_t rb = (((c & 0x00FF00FFu) * 249u + 0x03F603F6u) >> 11) & 0x001F001Fu;  // R5 at 16, B5 at 0
  return ((rb >> 5) & 0xF800u) | (to6(green(c)) << 5) | (rb & 31u);
}
[[gnu::always_inline]] constexpr Rgb unpack565(std::uint32_t p) {
  return rgb(from5(p >> 11), from6((p >> 5) & 63u), from5(p & 31u));
}

template <>
struct ColorTraits<PixelFormat::rgb565> {
  using Storage = std::uint16_t;
  static constexpr int per_pixel = 1;
  [[gnu::always_inline]] static Rgb load(const Storage* p) { return unpack565(*p); }
  [[gnu::always_inline]] static void store(Storage* p, Rgb c) { *p = static_cast<std::uint16_t>(pack565(c)); }
  [[gnu::always_inline]] static constexpr Rgb quantize(Rgb c) { return unpack565(pack565(c)); }
};

// RGB565 with its two bytes swapped in memory: the byte order SPI panels take.
[[gnu::always_inline]] constexpr std::uint32_t swap_bytes16(std::uint32_t p) { return ((p & 0xFFu) << 8) | ((p >> 8) & 0xFFu); }

template <>
struct ColorTraits<PixelFormat::rgb565_be> {
  using Storage = std::uint16_t;
  static constexpr int per_pixel = 1;
  [[gnu::always_inline]] static Rgb load(const Storage* p) { return unpack565(swap_bytes16(*p)); }
  [[gnu::always_inline]] static void store(Storage* p, Rgb c) { *p = static_cast<std::uint16_t>(swap_bytes16(pack565(c))); }
  [[gnu::always_inline]] static constexpr Rgb quantize(Rgb c) { return unpack565(pack565(c)); }
};

}  // namespace spanlight
