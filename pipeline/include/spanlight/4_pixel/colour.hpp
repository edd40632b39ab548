// Colour at a pixel: 8-bit levels in registers, the framebuffer's format in
// memory. Light and surface are combined in 8-bit levels, every step rounded
// to nearest, as the paper's passes do in an 8-bit framebuffer:
//   light   = min(255, ambient + sum of each projector's light)   (quantised to the format after each add)
//   pixel   = round(light * surface / 255)
//
// A colour travels as red and blue in two 16-bit lanes of one word (0x00RR00BB)
// and green in another, the shape the texture blend leaves it in: products of
// two 8-bit levels stay below 2^16 per lane, so red and blue are worked on together.
#pragma once

#include <cstdint>

#include "fixedpoint/lanes.hpp"
#include "spanlight/knobs.hpp"

namespace spanlight {

// A texel or colour as stored: 0x00RRGGBB.
using Rgb = std::uint32_t;

struct Colour {
  std::uint32_t rb;  // 0x00RR00BB
  std::uint32_t g;   // 0..255

  friend constexpr bool operator==(const Colour&, const Colour&) = default;
};

[[gnu::always_inline]] constexpr Colour colour_of(Rgb c) { return {c & 0x00FF00FFu, (c >> 8) & 255u}; }
[[gnu::always_inline]] constexpr Colour colour_of(std::uint32_t r, std::uint32_t g, std::uint32_t b) {
  return {(r << 16) | b, g};
}
[[gnu::always_inline]] constexpr std::uint32_t red(Colour c) { return c.rb >> 16; }
[[gnu::always_inline]] constexpr std::uint32_t green(Colour c) { return c.g; }
[[gnu::always_inline]] constexpr std::uint32_t blue(Colour c) { return c.rb & 255u; }
inline constexpr Colour white{0x00FF00FFu, 255u};
inline constexpr Colour black{0u, 0u};
// One test of both words, inline (GCC -Os calls the defaulted operator== out of line).
[[gnu::always_inline]] constexpr bool is_black(Colour c) { return (c.rb | c.g) == 0u; }

// round(a * b / 255) for a, b in [0, 255], exact (Blinn's trick).
[[gnu::always_inline]] constexpr std::uint32_t mul255(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t t = a * b + 128u;
  return (t + (t >> 8)) >> 8;
}

// light * surface per channel, mul255's rounding run on red and blue at once in
// their lanes (each lane's t = a * b + 128 < 2^16, so the lanes never meet).
[[gnu::always_inline]] inline Colour modulate(Colour light, Colour surface) {
  const std::uint32_t t = fixedpoint::lane_products(light.rb, surface.rb) + 0x00800080u;
  return {fixedpoint::bytes_1_3(fixedpoint::add_bytes_1_3(t, t)), mul255(light.g, surface.g)};
}

// base + light per channel, saturated at 255.
[[gnu::always_inline]] inline Colour add_light(Colour base, Colour light) {
  return {fixedpoint::add_bytes_saturated(base.rb, light.rb), fixedpoint::add_bytes_saturated(base.g, light.g)};
}

// ---- framebuffer formats ------------------------------------------------------

template <PixelFormat Format>
struct ColorTraits;

template <>
struct ColorTraits<PixelFormat::rgb888> {
  using Storage = std::uint8_t;
  static constexpr int per_pixel = 3;  // R, G, B bytes
  [[gnu::always_inline]] static Colour load(const Storage* p) { return colour_of(p[0], p[1], p[2]); }
  [[gnu::always_inline]] static void store(Storage* p, Colour c) {
    p[0] = static_cast<std::uint8_t>(c.rb >> 16);
    p[1] = static_cast<std::uint8_t>(c.g);
    p[2] = static_cast<std::uint8_t>(c.rb);
  }
  [[gnu::always_inline]] static constexpr Colour quantize(Colour c) { return c; }
};

// round(c * 31 / 255) and round(c * 63 / 255) without a divide (exact for c in [0, 255]).
[[gnu::always_inline]] constexpr std::uint32_t to5(std::uint32_t c) { return (c * 249u + 1014u) >> 11; }
[[gnu::always_inline]] constexpr std::uint32_t to6(std::uint32_t c) { return (c * 253u + 505u) >> 10; }
[[gnu::always_inline]] constexpr std::uint32_t from5(std::uint32_t c) { return (c << 3) | (c >> 2); }
[[gnu::always_inline]] constexpr std::uint32_t from6(std::uint32_t c) { return (c << 2) | (c >> 4); }

// To RGB565 in the low 16 bits (above them: don't care): red and blue rounded
// together in their lanes (255 * 249 + 1014 < 2^16: a lane's product never
// reaches the next), then red moved down beside blue and green put between.
[[gnu::always_inline]] inline std::uint32_t pack565(Colour c) {
  const std::uint32_t rb = (fixedpoint::opaque(249u) * c.rb + fixedpoint::opaque(0x03F603F6u)) >> 11;
  const std::uint32_t rb5 = rb & 0x001F001Fu;  // B5 at 0, R5 at 16
  const std::uint32_t g6 = (fixedpoint::opaque(253u) * c.g + 505u) >> 10;
  return rb5 | (rb5 >> 5) | (g6 << 5);
}
[[gnu::always_inline]] constexpr Colour unpack565(std::uint32_t p) {
  return colour_of(from5((p >> 11) & 31u), from6((p >> 5) & 63u), from5(p & 31u));
}

template <>
struct ColorTraits<PixelFormat::rgb565> {
  using Storage = std::uint16_t;
  static constexpr int per_pixel = 1;
  [[gnu::always_inline]] static Colour load(const Storage* p) { return unpack565(*p); }
  [[gnu::always_inline]] static void store(Storage* p, Colour c) { *p = static_cast<std::uint16_t>(pack565(c)); }
  [[gnu::always_inline]] static Colour quantize(Colour c) { return unpack565(pack565(c) & 0xFFFFu); }
};

// RGB565 with its two bytes swapped in memory: the byte order SPI panels take.
[[gnu::always_inline]] constexpr std::uint32_t swap_bytes16(std::uint32_t p) { return ((p & 0xFFu) << 8) | ((p >> 8) & 0xFFu); }

template <>
struct ColorTraits<PixelFormat::rgb565_be> {
  using Storage = std::uint16_t;
  static constexpr int per_pixel = 1;
  [[gnu::always_inline]] static Colour load(const Storage* p) { return unpack565(swap_bytes16(*p)); }
  [[gnu::always_inline]] static void store(Storage* p, Colour c) { *p = static_cast<std::uint16_t>(swap_bytes16(pack565(c))); }
  [[gnu::always_inline]] static Colour quantize(Colour c) { return unpack565(pack565(c) & 0xFFFFu); }
};

}  // namespace spanlight
