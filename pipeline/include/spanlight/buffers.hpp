// Caller-owned storage: colour in RGB888 or RGB565, depth in 16 or 24 bits
// (held in uint16_t or uint32_t). Nothing here allocates.
#pragma once

#include <cstdint>

#include "spanlight/features.hpp"
#include "spanlight/sample.hpp"

namespace spanlight {

template <PixelFormat Format>
struct ColorTraits;

template <>
struct ColorTraits<PixelFormat::rgb888> {
  using Storage = std::uint8_t;
  static constexpr int per_pixel = 3;
  [[gnu::always_inline]] static Rgb8 load(const Storage* p) { return {p[0], p[1], p[2]}; }
  [[gnu::always_inline]] static void store(Storage* p, Rgb8 c) {
    p[0] = c.r;
    p[1] = c.g;
    p[2] = c.b;
  }
  [[gnu::always_inline]] static Rgb8 quantize(Rgb8 c) { return c; }
};

template <>
struct ColorTraits<PixelFormat::rgb565> {
  using Storage = std::uint16_t;
  static constexpr int per_pixel = 1;
  // round(c * 31 / 255) and round(c * 63 / 255) without a divide.
  [[gnu::always_inline]] static constexpr std::uint16_t to5(std::uint8_t c) { return static_cast<std::uint16_t>((c * 249u + 1014u) >> 11); }
  [[gnu::always_inline]] static constexpr std::uint16_t to6(std::uint8_t c) { return static_cast<std::uint16_t>((c * 253u + 505u) >> 10); }
  [[gnu::always_inline]] static constexpr std::uint8_t from5(std::uint32_t c) { return static_cast<std::uint8_t>((c << 3) | (c >> 2)); }
  [[gnu::always_inline]] static constexpr std::uint8_t from6(std::uint32_t c) { return static_cast<std::uint8_t>((c << 2) | (c >> 4)); }
  [[gnu::always_inline]] static Rgb8 load(const Storage* p) { return {from5(*p >> 11u), from6((*p >> 5u) & 63u), from5(*p & 31u)}; }
  [[gnu::always_inline]] static void store(Storage* p, Rgb8 c) { *p = static_cast<std::uint16_t>((to5(c.r) << 11) | (to6(c.g) << 5) | to5(c.b)); }
  [[gnu::always_inline]] static Rgb8 quantize(Rgb8 c) {
    Storage s;
    store(&s, c);
    return load(&s);
  }
};

template <PixelFormat Format, typename DepthT>
struct FrameTarget {
  typename ColorTraits<Format>::Storage* color;  // width * height pixels, row 0 at the top
  DepthT* depth;                                 // width * height
  DepthT* const* shadow_maps;                    // one per projector (map_size^2), nullptr where unshadowed
  // One bit per pixel (tie_mask_bytes): a z-equal pass claims a pixel once, so
  // two surfaces that store the same depth there are not lit or modulated
  // twice. The first one drawn wins, as it does in the depth pass.
  std::uint8_t* tie_mask;
};

constexpr std::uint32_t tie_mask_bytes(std::uint32_t width, std::uint32_t height) { return (width * height + 7u) / 8u; }

// True the first time a pixel is claimed since the mask was cleared.
SPANLIGHT_PIXEL_INLINE bool claim_pixel(std::uint8_t* mask, std::int32_t i) {
  const auto bit = static_cast<std::uint8_t>(1u << (static_cast<std::uint32_t>(i) & 7u));
  std::uint8_t& byte = mask[static_cast<std::uint32_t>(i) >> 3];
  if (byte & bit) return false;
  byte = static_cast<std::uint8_t>(byte | bit);
  return true;
}

// Depth as stored: the top depth_bits of the Q1.30 window depth, cleared to all ones.
constexpr std::uint32_t depth_clear(int depth_bits) { return (1u << depth_bits) - 1u; }

// The stored depth with its constants worked out once per pass instead of at
// every pixel (depth bits are a run-time knob).
struct DepthFormat {
  int bits;
  int shift;           // 30 - bits
  std::uint32_t top;   // the largest value a surface stores: never the clear value
  std::uint32_t clear;
  constexpr explicit DepthFormat(int depth_bits)
      : bits(depth_bits), shift(30 - depth_bits), top(depth_clear(depth_bits) - 1u), clear(depth_clear(depth_bits)) {}
  [[gnu::always_inline]] constexpr std::uint32_t store(std::int32_t z_q30) const {
    const std::uint32_t z = static_cast<std::uint32_t>(z_q30 < 0 ? 0 : z_q30) >> shift;
    return z > top ? top : z;
  }
};

constexpr std::uint32_t depth_store(std::int32_t z_q30, int depth_bits) { return DepthFormat(depth_bits).store(z_q30); }

}  // namespace spanlight
