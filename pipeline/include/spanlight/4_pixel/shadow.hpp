// Stage 4b, shadow maps: the compare of condition 4, r/q - bias <= D. `nearest` reads
// the texel containing (s/q, t/q); `pcf2x2` weighs the four comparisons around
// it bilinearly (texel centres at half-integers, indices clamped to the map).
// Depth is compared in Q1.30; the map keeps its top depth_bits.
#pragma once

#include <algorithm>
#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

inline constexpr int shadow_proj_frac_bits = 28;  // s/q, t/q, r/q arrive in Q3.28

// A texel lets the light through when r/q - bias <= its depth: with the map's depth d (its top
// depth_bits of Q1.30) that is 4 r - bias <= d 2^k, k = 30 - depth_bits, and for an integer d
// the same as ceil((4 r - bias) / 2^k) <= d: one 32-bit compare a tap against `need`.
// r in [0, 1] (Q3.28, inside the frustum) and bias in [0, max_shadow_bias] (1.99 in Q1.30, scene.hpp), so
// bias - 4 r lies in [-2^30, 2^31): one word, and the ceiling is minus the floor of its negation.
[[gnu::always_inline]] constexpr std::uint32_t shadow_need(std::int32_t r, std::int32_t bias, int depth_bits) {
  const std::int32_t need = -((bias - (r << (30 - shadow_proj_frac_bits))) >> (30 - depth_bits));  // >>: floor
  return need < 0 ? 0u : static_cast<std::uint32_t>(need);  // every depth >= 0 lets a negative one through
}

// Map indices clamp to [0, size - 1]; rows are stored from the top, y counts from the bottom.
[[gnu::always_inline]] constexpr std::int32_t clamp_index(std::int32_t i, std::int32_t size) {
  return std::clamp(i, std::int32_t{0}, size - 1);
}
template <typename DepthT>
[[gnu::always_inline]] inline const DepthT* shadow_row(const DepthT* map, std::int32_t size, std::int32_t y_from_bottom) {
  return map + (size - 1 - clamp_index(y_from_bottom, size)) * size;
}

// Fraction of light let through, in 1/256 (0..256), at (s, t, r) inside the frustum (each in [0, 1], Q3.28).
template <bool Pcf, typename DepthT>
[[gnu::always_inline]] inline std::uint32_t shadow_factor(const ProjectorData& p, const DepthT* map, std::int32_t s, std::int32_t t,
                                   std::int32_t r, int depth_bits) {
  const std::int32_t size = p.map_size;
  const std::uint32_t need = shadow_need(r, p.bias, depth_bits);
  if constexpr (Pcf) {
    if (p.filter == ShadowFilter::pcf2x2) {
      // Map coordinates with 8 fraction bits, shifted to texel centres.
      const std::int32_t xs = fixedpoint::mul_u28_u13_shifted(s, size, shadow_proj_frac_bits - 8) - 128;
      const std::int32_t ys = fixedpoint::mul_u28_u13_shifted(t, size, shadow_proj_frac_bits - 8) - 128;
      const std::int32_t x0 = xs >> 8, y0 = ys >> 8;
      const std::uint32_t fx = static_cast<std::uint32_t>(xs) & 255u, fy = static_cast<std::uint32_t>(ys) & 255u;
      const DepthT *row0 = shadow_row(map, size, y0), *row1 = shadow_row(map, size, y0 + 1);
      const std::int32_t xa = clamp_index(x0, size), xb = clamp_index(x0 + 1, size);  // each clamped once for both rows
      const std::uint32_t lit = (256 - fx) * (256 - fy) * (row0[xa] >= need) + fx * (256 - fy) * (row0[xb] >= need) +
                                (256 - fx) * fy * (row1[xa] >= need) + fx * fy * (row1[xb] >= need);
      return (lit + 128u) >> 8;
    }
  }
  const std::int32_t x = fixedpoint::mul_u28_u13_shifted(s, size, shadow_proj_frac_bits);
  const std::int32_t y = fixedpoint::mul_u28_u13_shifted(t, size, shadow_proj_frac_bits);
  return shadow_row(map, size, y)[clamp_index(x, size)] >= need ? 256u : 0u;
}

}  // namespace spanlight
