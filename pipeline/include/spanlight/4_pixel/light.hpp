// Stage 4c, a projector's light at a pixel (docs/scene-format.md, "What a pixel
// shows"): lit when q > 0, (s/q, t/q) in [0, 1]^2, r/q in [0, 1] and (with
// shadows) r/q - bias <= D; then colour * image(s/q, t/q) * shadow [* falloff(r/q)],
// in 8-bit levels.
#pragma once

#include <algorithm>
#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "spanlight/4_pixel/colour.hpp"
#include "spanlight/4_pixel/shadow.hpp"
#include "spanlight/4_pixel/texture.hpp"
#include "spanlight/features.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

inline constexpr std::int32_t proj_one = std::int32_t{1} << shadow_proj_frac_bits;  // 1.0 in Q3.28

// What a pass needs of one projector, its shadow map typed.
template <typename DepthT>
struct Light {
  const ProjectorData* projector;
  const TextureData* image;
  const DepthT* shadow_map;     // nullptr: no shadows
  const TextureData* falloff;   // nullptr: none (scene format 2)
};

// Whether (s, t, r) (Q3.28) lies in the projector's frustum: conditions 2 and 3.
[[gnu::always_inline]] constexpr bool in_frustum(std::int32_t s, std::int32_t t, std::int32_t r) {
  // One unsigned compare each: a negative value wraps far above 1.0.
  return static_cast<std::uint32_t>(s) <= static_cast<std::uint32_t>(proj_one) &&
         static_cast<std::uint32_t>(t) <= static_cast<std::uint32_t>(proj_one) &&
         static_cast<std::uint32_t>(r) <= static_cast<std::uint32_t>(proj_one);
}

// The falloff texture at (r/q, 0.5), clamped to its edge, with its own filter
// (never mipmapped), per channel in Q.16 (1.0 = 65536). r in [0, 1] (Q3.28).
// The unrounded bilinear sum f (8-bit levels * 2^16) becomes f / 255 in Q.16 as
// (f / 2^8) * 257 / 2^8: 257 / 2^16 is 1/255 within 2^-16, a relative error
// below 2^-15 after the rounding.
[[gnu::always_inline]] inline Texel16 falloff_factor(const TextureData& falloff, std::int32_t r) {
  const TextureLevel& level = falloff.levels[0];
  Texel16 f;
  const std::int32_t x8 = fixedpoint::mul_u28_u13_shifted(r, level.width, shadow_proj_frac_bits - 8);
  if (falloff.filter == Filter::nearest) {
    const std::int32_t x = std::min<std::int32_t>(x8 >> 8, level.width - 1);
    const std::int32_t y = level.height / 2;  // floor(0.5 * height), below height
    const Colour c = colour_of(level.texels[y * level.stride + x]);
    f = {red(c) << 16, green(c) << 16, blue(c) << 16};
  } else {
    // Texel centres at half-integers: x - 1/2 clamped to [0, width - 1], y = height / 2 - 1/2.
    std::int32_t x = x8 - 128;
    const std::int32_t x_max = (level.width - 1) << 8;
    x = std::clamp(x, std::int32_t{0}, x_max);
    const std::int32_t y = level.height * 128 - 128;
    f = bilinear_texel16(taps_at(level.texels + (y >> 8) * level.stride + (x >> 8), level.stride, static_cast<std::uint32_t>(x) & 255u,
                                 static_cast<std::uint32_t>(y) & 255u));
  }
  auto q16 = [](std::uint32_t v) SPANLIGHT_LAMBDA_INLINE_ATTR { return ((v >> 8) * 257u + 128u) >> 8; };
  return {q16(f.r), q16(f.g), q16(f.b)};
}

// The light a projector adds at a pixel inside its frustum with q > 0, before saturation.
// Out of line: a pixel loop that inlines it spills its stepped values around it (measured
// with tools/qemu_icount/measure_elf.sh: spot_shadow -11 % on Cortex-M7, +1 % on M0+ for
// 3.8 KB less flash).
template <Features F, typename DepthT>
[[gnu::noinline]] Colour projector_light(const Light<DepthT>& light, std::int32_t s, std::int32_t t, std::int32_t r,
                                                     int depth_bits) {
  std::uint32_t shadow = 256;  // condition 4, in 1/256
  if constexpr (F.shadows) {
    if (light.shadow_map != nullptr) {
      shadow = shadow_factor<F.pcf>(*light.projector, light.shadow_map, s, t, r, depth_bits);
      if (shadow == 0) return black;
    }
  }
  const TextureLevel& level = light.image->levels[0];
  // Image texel coordinates with 8 sub-texel bits: s in [0, 1] Q.28 times the size (< 2^13).
  const std::int32_t x8 = fixedpoint::mul_u28_u13_shifted(s, level.width, shadow_proj_frac_bits - 8);
  const std::int32_t y8 = fixedpoint::mul_u28_u13_shifted(t, level.height, shadow_proj_frac_bits - 8);
  const Texel16 texel = projector_texel(*light.image, x8, y8, F.bilinear);
  // colour (Q8.8) * shadow (Q.8) [* falloff (Q.16), rounded back to Q.16] * texel (8.16, unrounded),
  // rounded once to 8-bit levels.
  const std::uint16_t* colour = light.projector->color;
  std::uint32_t scale[3] = {colour[0] * shadow, colour[1] * shadow, colour[2] * shadow};  // < 2^16 * 2^8
  if constexpr (F.falloff) {
    if (light.falloff != nullptr) {
      const Texel16 f = falloff_factor(*light.falloff, r);
      const std::uint32_t factor[3] = {f.r, f.g, f.b};
      for (int c = 0; c < 3; ++c)  // < 2^24 * 2^16: 64 bits; rounded back below 2^24
        scale[c] = static_cast<std::uint32_t>((fixedpoint::mul_u32(scale[c], factor[c]) + 0x8000u) >> 16);
    }
  }
  auto channel = [&](std::uint32_t c, std::uint32_t v) SPANLIGHT_LAMBDA_INLINE_ATTR {
    const std::uint32_t levels = fixedpoint::mul_u25_u24_rounded_high(c, v);  // c < 2^24, v < 2^24
    return std::min<std::uint32_t>(levels, 255u);
  };
  return colour_of(channel(scale[0], texel.r), channel(scale[1], texel.g), channel(scale[2], texel.b));
}

}  // namespace spanlight
