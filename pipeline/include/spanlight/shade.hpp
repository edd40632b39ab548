// Stage 6, shading: the per-pixel work of each pass, in the paper's order.
//   depth + ambient : z <  Z  -> Z = z, C = ambient
//   light j         : z == Z  -> C = min(1, C + lit_j * shadow_j * colour_j * image_j)
//   modulate        : z == Z  -> C = C * surface
//   fused           : z <  Z  -> all of the above at once, with the same
//                               quantisation steps, so the bytes are the same.
// Colour arithmetic is in 8-bit levels; every step rounds to nearest.
#pragma once

#include <cstdint>

#include "spanlight/buffers.hpp"
#include "spanlight/shadow.hpp"
#include "spanlight/span.hpp"

namespace spanlight {

// round(a * b / 255) for a, b in [0, 255], exact (Blinn's trick).
[[gnu::always_inline]] constexpr std::uint8_t mul255(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t t = a * b + 128u;
  return static_cast<std::uint8_t>((t + (t >> 8)) >> 8);
}

[[gnu::always_inline]] constexpr std::uint8_t add_saturate(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t s = a + b;
  return static_cast<std::uint8_t>(s > 255u ? 255u : s);
}

struct LightContext {
  const ProjectorData* projector;
  const TextureData* image;
  const void* shadow_map;  // DepthT*, typed by the caller
};

// Light one projector adds at a pixel, in 8-bit levels (before saturation).
template <typename F, typename DepthT, int P>
SPANLIGHT_PIXEL_INLINE Rgb8 projector_light(const LightContext& ctx, const PointValues<P>& v, int j, int depth_bits) {
  constexpr std::int32_t one = 1 << proj_frac_bits;
  if (!v.front[j]) return {0, 0, 0};                                       // 1. q > 0
  if (v.s[j] < 0 || v.s[j] > one || v.t[j] < 0 || v.t[j] > one) return {0, 0, 0};  // 2. inside the sides
  if (v.r[j] < 0 || v.r[j] > one) return {0, 0, 0};                         // 3. between near and far
  std::uint32_t shadow = 256;                                               // 4. shadow compare, in 1/256
  if constexpr (F::shadows) {
    if (ctx.projector->shadows) {
      shadow = shadow_factor<F::pcf>(*ctx.projector, static_cast<const DepthT*>(ctx.shadow_map), v.s[j], v.t[j],
                                     v.r[j], depth_bits);
      if (shadow == 0) return {0, 0, 0};
    }
  }
  // Image texel coordinates with 8 sub-texel bits: s in [0, 1] Q.28 times the size.
  const std::int32_t x = static_cast<std::int32_t>(fixedpoint::mul_s32(v.s[j], ctx.image->width) >> (proj_frac_bits - 8));
  const std::int32_t y = static_cast<std::int32_t>(fixedpoint::mul_s32(v.t[j], ctx.image->height) >> (proj_frac_bits - 8));
  const Texel16 texel = sample16_border<F::bilinear>(*ctx.image, x, y, 8);
  // colour (Q8.8) * texel (8.16, unrounded) * shadow (Q.8): rounded once, to 8-bit levels.
  auto channel = [&](std::uint16_t colour, std::uint32_t t) {
    const std::uint64_t product = fixedpoint::mul_u32(colour * shadow, t);  // < 2^16 * 2^9 * 2^24
    const std::uint64_t levels = (product + (std::uint64_t{1} << 31)) >> 32;
    return static_cast<std::uint8_t>(levels > 255u ? 255u : levels);
  };
  return {channel(ctx.projector->color[0], texel.r), channel(ctx.projector->color[1], texel.g),
          channel(ctx.projector->color[2], texel.b)};
}

SPANLIGHT_PIXEL_INLINE Rgb8 add_light(Rgb8 base, Rgb8 light) {
  return {add_saturate(base.r, light.r), add_saturate(base.g, light.g), add_saturate(base.b, light.b)};
}

SPANLIGHT_PIXEL_INLINE Rgb8 modulate(Rgb8 light, Rgb8 surface) {
  return {mul255(light.r, surface.r), mul255(light.g, surface.g), mul255(light.b, surface.b)};
}

// object colour * texture(u, v), 8-bit levels.
template <typename F, int P>
SPANLIGHT_PIXEL_INLINE Rgb8 surface_colour(const ObjectData& object, const TextureData* texture, const PointValues<P>& v) {
  if (texture == nullptr) return {object.color[0], object.color[1], object.color[2]};
  const Rgb8 t = sample<F::bilinear>(*texture, v.u, v.v, object.uv_frac_bits, texture->wrap);
  if ((object.color[0] & object.color[1] & object.color[2]) == 255) return t;  // white: mul255 is the identity
  return {mul255(object.color[0], t.r), mul255(object.color[1], t.g), mul255(object.color[2], t.b)};
}

// Calls fn(surface), surface(values) giving the object's surface colour at a
// pixel, with the best form chosen once for a run of pixels: the colour itself
// when untextured, the repeat-wrapped bilinear fast path (white objects), or
// surface_colour(). Every form gives surface_colour()'s bytes.
template <typename F, int P, typename Fn>
SPANLIGHT_PIXEL_INLINE std::int64_t with_run_surface(const ObjectData& object, const TextureData* texture, Fn&& fn) {
  if (texture == nullptr) {
    const Rgb8 colour{object.color[0], object.color[1], object.color[2]};
    return fn([colour](const PointValues<P>&) SPANLIGHT_LAMBDA_INLINE { return colour; });
  }
  if constexpr (F::bilinear) {
    const bool white = (object.color[0] & object.color[1] & object.color[2]) == 255;
    if (texture->filter == Filter::bilinear && texture->wrap == Wrap::repeat && white &&
        RepeatTexture::fits(object.uv_frac_bits)) {
      const RepeatTexture tex(*texture, object.uv_frac_bits);
      return fn([&tex](const PointValues<P>& v) SPANLIGHT_LAMBDA_INLINE { return unpack_rgb(sample_bilinear_packed(tex, v.u, v.v)); });
    }
  }
  return fn([&](const PointValues<P>& v) SPANLIGHT_LAMBDA_INLINE { return surface_colour<F>(object, texture, v); });
}

}  // namespace spanlight
