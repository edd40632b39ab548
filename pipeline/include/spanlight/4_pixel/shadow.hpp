// Stage 4b, shadow maps: the compare of condition 4, r/q - bias <= D. `nearest` reads
// the texel containing (s/q, t/q); `pcf2x2` weighs the four comparisons around
// it bilinearly (texel centres at half-integers, indices clamped to the map).
// Depth is compared in Q1.30; the map keeps its top depth_bits.
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

inline constexpr int shadow_proj_frac_bits = 28;  // s/q, t/q, r/q arrive in Q3.28

template <typename DepthT>
[[gnu::always_inline]] inline bool shadow_lit_at(const DepthT* map, std::int32_t size, std::int32_t x, std::int32_t y_from_bottom,
                          std::int64_t r_minus_bias_q30, int depth_bits) {
  x = x < 0 ? 0 : (x >= size ? size - 1 : x);
  y_from_bottom = y_from_bottom < 0 ? 0 : (y_from_bottom >= size ? size - 1 : y_from_bottom);
  const std::uint32_t stored = map[(size - 1 - y_from_bottom) * size + x];
  const std::int64_t d_q30 = std::int64_t{stored} << (30 - depth_bits);
  return r_minus_bias_q30 <= d_q30;
}

// Fraction of light let through, in 1/256 (0..256).
template <bool Pcf, typename DepthT>
[[gnu::always_inline]] inline std::uint32_t shadow_factor(const ProjectorData& p, const DepthT* map, std::int32_t s, std::int32_t t,
                                   std::int32_t r, int depth_bits) {
  const std::int32_t size = p.map_size;
  const std::int64_t r_biased = (std::int64_t{r} << (30 - shadow_proj_frac_bits)) - p.bias;
  if constexpr (Pcf) {
    if (p.filter == ShadowFilter::pcf2x2) {
      // Map coordinates with 8 fraction bits, shifted to texel centres.
      const std::int32_t xs = static_cast<std::int32_t>(fixedpoint::mul_s32(s, size) >> (shadow_proj_frac_bits - 8)) - 128;
      const std::int32_t ys = static_cast<std::int32_t>(fixedpoint::mul_s32(t, size) >> (shadow_proj_frac_bits - 8)) - 128;
      const std::int32_t x0 = xs >> 8, y0 = ys >> 8;
      const std::uint32_t fx = static_cast<std::uint32_t>(xs) & 255u, fy = static_cast<std::uint32_t>(ys) & 255u;
      const std::uint32_t lit = (256 - fx) * (256 - fy) * shadow_lit_at(map, size, x0, y0, r_biased, depth_bits) +
                                fx * (256 - fy) * shadow_lit_at(map, size, x0 + 1, y0, r_biased, depth_bits) +
                                (256 - fx) * fy * shadow_lit_at(map, size, x0, y0 + 1, r_biased, depth_bits) +
                                fx * fy * shadow_lit_at(map, size, x0 + 1, y0 + 1, r_biased, depth_bits);
      return (lit + 128u) >> 8;
    }
  }
  const std::int32_t x = static_cast<std::int32_t>(fixedpoint::mul_s32(s, size) >> shadow_proj_frac_bits);
  const std::int32_t y = static_cast<std::int32_t>(fixedpoint::mul_s32(t, size) >> shadow_proj_frac_bits);
  return shadow_lit_at(map, size, x, y, r_biased, depth_bits) ? 256u : 0u;
}

}  // namespace spanlight
