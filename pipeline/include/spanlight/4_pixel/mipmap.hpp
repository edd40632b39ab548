// Stage 4e, trilinear sampling (scene format 2): a run's lambda (3_span/lod.hpp)
// picks levels k = floor(d) and k + 1 (the last clamped), d = min(lambda, last
// level), and mixes their bilinear samples by f = d - k with 8 fraction bits:
//
//   c = round(((256 - f) b_k + f b_(k+1)) / 2^8),   lambda <= 0: c = b_0,
//
// from the bilinear sums before their rounding (8-bit levels * 2^16), so the
// mix is rounded once. Each level is read at the same (u, v): the walk's
// coordinates point half a level-0 texel back (bilinear's centres), and level
// k's centres sit 2^k - 1 half level-0 texels further back.
#pragma once

#include <cstdint>

#include "spanlight/3_span/lod.hpp"
#include "spanlight/4_pixel/colour.hpp"
#include "spanlight/4_pixel/texture.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

// One level as the mix reads it, coordinates in the walk's scale for the texture.
struct MipLevel {
  TexelGrid grid;       // repeat: x_shift, y_shift of this level (up to 32); else frac = uv_frac_bits + k
  std::uint32_t back_x, back_y;  // subtracted from the walk's coordinates
};

// Level k of a texture whose level-0 grid (with the object's uv_frac_bits) is `g0`.
constexpr MipLevel mip_level(const TextureData& texture, const TexelGrid& g0, int k) {
  MipLevel m{};
  const TextureLevel& level = texture.levels[k];
  const auto extra = (std::uint32_t{1} << k) - 1u;  // half level-0 texels further back
  if (texture.wrap == Wrap::repeat) {
    m.grid = {level.texels, level.stride, level.width, level.height, g0.frac, g0.x_shift + k, g0.y_shift + k};
    m.back_x = extra << (g0.x_shift - 1);
    m.back_y = extra << (g0.y_shift - 1);
  } else {
    m.grid = texel_grid(level, g0.frac + k);
    m.back_x = m.back_y = extra << (g0.frac - 1);
  }
  return m;
}

// A repeating level's sums: a side of one texel (shift 32) reads texel 0 and its frame copy.
[[gnu::always_inline]] inline BilinearSums repeat_level_sums(const TexelGrid& g, std::uint32_t x, std::uint32_t y) {
  const std::uint32_t x0 = g.x_shift >= 32 ? 0u : x >> g.x_shift, y0 = g.y_shift >= 32 ? 0u : y >> g.y_shift;
  const std::uint32_t fx = (x >> (g.x_shift - 8)) & 255u, fy = (y >> (g.y_shift - 8)) & 255u;
  return footprint_sums({g.texels + static_cast<std::int32_t>(y0) * g.stride + static_cast<std::int32_t>(x0), fx, fy}, g.stride);
}

[[gnu::always_inline]] inline BilinearSums level_sums(const MipLevel& m, Wrap wrap, std::uint32_t x, std::uint32_t y) {
  x -= m.back_x;
  y -= m.back_y;
  if (wrap == Wrap::repeat) return repeat_level_sums(m.grid, x, y);
  if (wrap == Wrap::clamp) return bilinear_clamp_sums(m.grid, static_cast<std::int32_t>(x), static_cast<std::int32_t>(y));
  return bilinear_border_sums(m.grid, static_cast<std::int32_t>(x), static_cast<std::int32_t>(y));
}

// The sampler of one run: its two levels and their mix.
struct TrilinearSampler {
  MipLevel lo, hi;
  std::uint32_t f;  // weight of hi, /256
  Wrap wrap;

  static constexpr TrilinearSampler of(const TextureData& texture, const TexelGrid& g0, std::int32_t lod) {
    const std::int32_t last = (texture.level_count - 1) << lod_frac_bits;
    const std::int32_t d = lod <= 0 ? 0 : (lod > last ? last : lod);
    const int k = d >> lod_frac_bits;
    const int k1 = k + 1 < texture.level_count ? k + 1 : k;
    return {mip_level(texture, g0, k), mip_level(texture, g0, k1), static_cast<std::uint32_t>(d & 255), texture.wrap};
  }

  [[gnu::always_inline]] Colour operator()(std::uint32_t x, std::uint32_t y) const {
    const Texel16 a = unrounded(level_sums(lo, wrap, x, y));
    if (f == 0) return colour_of((a.r + 0x8000u) >> 16, (a.g + 0x8000u) >> 16, (a.b + 0x8000u) >> 16);
    const Texel16 b = unrounded(level_sums(hi, wrap, x, y));
    // (256 - f) a + f b <= 255 * 2^24 < 2^32.
    auto mix = [&](std::uint32_t p, std::uint32_t q) { return ((256u - f) * p + f * q + (1u << 23)) >> 24; };
    return colour_of(mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b));
  }
};

}  // namespace spanlight
