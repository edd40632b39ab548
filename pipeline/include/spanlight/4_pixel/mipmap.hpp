// Stage 4e, trilinear sampling (scene format 2): a pixel's lambda (3_span/lod.hpp,
// linear along a run that keeps one level band) picks levels k = floor(d) and
// k + 1, d = lambda in Q.8 clamped to [0, last level], and mixes their bilinear
// samples by f = d - k with 8 fraction bits:
//
//   c = round(((256 - f) b_k + f b_(k+1)) / 2^8),   lambda <= 0: c = b_0,
//
// from the bilinear sums before their rounding (8-bit levels * 2^16), so the
// mix is rounded once. Each level is read at the same (u, v): the walk's
// coordinates point half a level-0 texel back (bilinear's centres), and level
// k's centres sit 2^k - 1 half level-0 texels further back.
#pragma once

#include <algorithm>
#include <cstdint>

#include "spanlight/3_span/lod.hpp"  // RunLevel
#include "spanlight/4_pixel/colour.hpp"
#include "spanlight/4_pixel/texture.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

// One level as the mix reads it, coordinates in the walk's scale for the texture.
struct MipLevel {
  TexelGrid grid;       // repeat: x_shift, y_shift of this level (up to 32); else frac = uv_frac_bits + k
  std::uint32_t back_x, back_y;  // subtracted from the walk's coordinates
  int x_down, y_down;            // repeat: x_shift - 8, y_shift - 8 (the index and weight bits' place)
};

// Level k of a texture whose level-0 grid (with the object's uv_frac_bits) is `g0`.
constexpr MipLevel mip_level(const TextureData& texture, const TexelGrid& g0, int k) {
  // Every field set in each branch, no zeroing first (a memset call at -Os).
  const TextureLevel& level = texture.levels[k];
  const auto extra = (std::uint32_t{1} << k) - 1u;  // half level-0 texels further back
  if (texture.wrap == Wrap::repeat) {
    // A side of one texel reads the same texel at both taps: its shift stops at 32.
    const int x_shift = std::min(g0.x_shift + k, 32), y_shift = std::min(g0.y_shift + k, 32);
    return {{level.texels, level.stride, level.width, level.height, g0.frac, x_shift, y_shift},
            extra << (g0.x_shift - 1), extra << (g0.y_shift - 1), x_shift - 8, y_shift - 8};
  }
  return {texel_grid(level, g0.frac + k), extra << (g0.frac - 1), extra << (g0.frac - 1), 0, 0};
}

// A repeating level's taps. The top shift - 8 bits hold the texel index and the
// 8-bit weight: one shift below 32 (shift <= 32), and a side of one texel (shift
// 32) reads texel 0 and its frame copy.
[[gnu::always_inline]] inline Taps repeat_level_taps(const MipLevel& m, std::uint32_t x, std::uint32_t y) {
  const TexelGrid& g = m.grid;
  const std::uint32_t xt = x >> m.x_down, yt = y >> m.y_down;
  const std::uint32_t x0 = xt >> 8, y0 = yt >> 8, fx = xt & 255u, fy = yt & 255u;
  return taps_at(g.texels + static_cast<std::int32_t>(y0) * g.stride + static_cast<std::int32_t>(x0), g.stride, fx, fy);
}

template <Wrap W>
[[gnu::always_inline]] inline Taps level_taps(const MipLevel& m, std::uint32_t x, std::uint32_t y) {
  x -= m.back_x;
  y -= m.back_y;
  if constexpr (W == Wrap::repeat) return repeat_level_taps(m, x, y);
  else if constexpr (W == Wrap::clamp) return bilinear_clamp_taps(m.grid, static_cast<std::int32_t>(x), static_cast<std::int32_t>(y));
  else return bilinear_border_taps(m.grid, static_cast<std::int32_t>(x), static_cast<std::int32_t>(y));
}

// One level of a run, read alone (lambda <= 0, or the last level).
template <Wrap W>
struct OneLevelSampler {
  MipLevel m;
  [[gnu::always_inline]] Colour operator()(std::uint32_t x, std::uint32_t y, std::int32_t) const {
    return bilinear_colour(level_taps<W>(m, x, y));
  }
};

// Levels k and k + 1 mixed by the pixel's weight f_i = (base + i step) >> 8.
template <Wrap W>
struct TwoLevelSampler {
  MipLevel lo, hi;
  std::int32_t base, step;

  [[gnu::always_inline]] Colour operator()(std::uint32_t x, std::uint32_t y, std::int32_t i) const {
    const Texel16 a = bilinear_texel16(level_taps<W>(lo, x, y));
    const Texel16 b = bilinear_texel16(level_taps<W>(hi, x, y));
    const auto f = static_cast<std::uint32_t>((base + i * step) >> 8);  // in [0, 256): the run keeps one level band
    // (256 - f) a + f b = 256 a + f (b - a), one product: the sum is <= 255 * 2^24 < 2^32,
    // so the unsigned arithmetic mod 2^32 (b - a may wrap) gives it exactly.
    auto mix = [&](std::uint32_t p, std::uint32_t q) SPANLIGHT_LAMBDA_INLINE_ATTR { return ((p << 8) + f * (q - p) + (1u << 23)) >> 24; };
    return colour_of(mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b));
  }
};

// Calls sampled with the run's sampler (3_span/lod.hpp, RunLevel): one_level is
// settled here once per run, so the loop of pixels carries no test of it (each
// sampler is its own loop).
template <Wrap W, typename Fn>
[[gnu::always_inline]] inline void with_run_levels(const TextureData& texture, const TexelGrid& g0, const RunLevel& level, Fn&& sampled) {
  const MipLevel lo = mip_level(texture, g0, level.level);
  if (level.one_level) return sampled(OneLevelSampler<W>{lo});
  sampled(TwoLevelSampler<W>{lo, mip_level(texture, g0, level.level + 1), level.base, level.step});
}

}  // namespace spanlight
