// Stage 4c, a projector's light at a pixel (docs/scene-format.md, "What a pixel
// shows"): lit when q > 0, (s/q, t/q) in [0, 1]^2, r/q in [0, 1] and (with
// shadows) r/q - bias <= D; then colour * image(s/q, t/q) * shadow, in 8-bit levels.
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "spanlight/4_pixel/colour.hpp"
#include "spanlight/4_pixel/shadow.hpp"
#include "spanlight/4_pixel/texture.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

inline constexpr std::int32_t proj_one = std::int32_t{1} << shadow_proj_frac_bits;  // 1.0 in Q3.28

// What a pass needs of one projector, its shadow map typed.
template <typename DepthT>
struct Light {
  const ProjectorData* projector;
  const TextureData* image;
  const DepthT* shadow_map;  // nullptr: no shadows
};

// Whether (s, t, r) (Q3.28) lies in the projector's frustum: conditions 2 and 3.
[[gnu::always_inline]] constexpr bool in_frustum(std::int32_t s, std::int32_t t, std::int32_t r) {
  // One unsigned compare each: a negative value wraps far above 1.0.
  return static_cast<std::uint32_t>(s) <= static_cast<std::uint32_t>(proj_one) &&
         static_cast<std::uint32_t>(t) <= static_cast<std::uint32_t>(proj_one) &&
         static_cast<std::uint32_t>(r) <= static_cast<std::uint32_t>(proj_one);
}

// The light a projector adds at a pixel inside its frustum with q > 0, before saturation.
template <bool Bilinear, bool Shadows, bool Pcf, typename DepthT>
[[gnu::always_inline]] inline Colour projector_light(const Light<DepthT>& light, std::int32_t s, std::int32_t t, std::int32_t r,
                                                  int depth_bits) {
  std::uint32_t shadow = 256;  // condition 4, in 1/256
  if constexpr (Shadows) {
    if (light.shadow_map != nullptr) {
      shadow = shadow_factor<Pcf>(*light.projector, light.shadow_map, s, t, r, depth_bits);
      if (shadow == 0) return black;
    }
  }
  const TextureLevel& level = light.image->levels[0];
  // Image texel coordinates with 8 sub-texel bits: s in [0, 1] Q.28 times the size (< 2^13).
  const auto x8 = static_cast<std::int32_t>(fixedpoint::mul_s32(s, level.width) >> (shadow_proj_frac_bits - 8));
  const auto y8 = static_cast<std::int32_t>(fixedpoint::mul_s32(t, level.height) >> (shadow_proj_frac_bits - 8));
  const Texel16 texel = projector_texel(*light.image, x8, y8, Bilinear);
  // colour (Q8.8) * texel (8.16, unrounded) * shadow (Q.8), rounded once to 8-bit levels.
  const std::uint16_t* colour = light.projector->color;
  auto channel = [&](std::uint16_t c, std::uint32_t v) {
    const std::uint64_t product = fixedpoint::mul_u32(c * shadow, v);  // < 2^16 * 2^9 * 2^24
    const std::uint64_t levels = (product + (std::uint64_t{1} << 31)) >> 32;
    return levels > 255u ? 255u : static_cast<std::uint32_t>(levels);
  };
  return colour_of(channel(colour[0], texel.r), channel(colour[1], texel.g), channel(colour[2], texel.b));
}

}  // namespace spanlight
