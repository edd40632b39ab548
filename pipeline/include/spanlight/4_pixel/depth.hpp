// Depth as stored: the top depth_bits of the window depth (Q0.32 while a span
// steps it), cleared to all ones; a surface never stores the clear value, so a
// z-equal pass can tell a covered pixel from the background.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

namespace spanlight {

constexpr std::uint32_t depth_clear(int depth_bits) { return (1u << depth_bits) - 1u; }

// The stored depth's constants, worked out once per pass (depth bits are a
// run-time knob on the host; FixedBits, a firmware's baked one, makes the
// store a shift by a constant).
template <int FixedBits = 0>
struct DepthFormat {
  int shift;            // 32 - bits: Q0.32 to stored
  std::uint32_t clear;  // all ones
  // The largest Q0.32 depth a span may step to: stored, it is clear - 1 (walk.hpp keeps
  // every stepped depth at or below it, so the store needs no clamp).
  std::uint32_t z_limit;
  constexpr explicit DepthFormat(int depth_bits)
      : shift(32 - depth_bits), clear(depth_clear(depth_bits)), z_limit(((clear - 1u) << (32 - depth_bits)) | ((1u << (32 - depth_bits)) - 1u)) {}
  [[gnu::always_inline]] constexpr std::uint32_t store(std::uint32_t z_q32) const {
    if constexpr (FixedBits != 0) return z_q32 >> (32 - FixedBits);
    else return z_q32 >> shift;
  }
  // The same for a depth that may lie beyond z_limit (a span evaluated per pixel).
  [[gnu::always_inline]] constexpr std::uint32_t store_clamped(std::uint32_t z_q32) const {
    return store(std::min(z_q32, z_limit));
  }
};

// One bit per pixel: a z-equal pass claims a pixel once, so two surfaces that
// store the same depth there are not lit or modulated twice. The first one
// drawn wins, as it does in the depth pass.
constexpr std::uint32_t tie_mask_bytes(std::uint32_t pixels) { return (pixels + 7u) / 8u; }

// True the first time a pixel is claimed since the mask was cleared.
[[gnu::always_inline]] inline bool claim_pixel(std::uint8_t* mask, std::uint32_t i) {
  const auto bit = static_cast<std::uint8_t>(1u << (i & 7u));
  std::uint8_t& byte = mask[i >> 3];
  if (byte & bit) return false;
  byte = static_cast<std::uint8_t>(byte | bit);
  return true;
}

}  // namespace spanlight
