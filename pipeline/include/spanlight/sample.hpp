// Stage 5, sampling: nearest and bilinear texel fetches with repeat, clamp and
// border. Coordinates arrive in texels with `frac` sub-texel bits; t = 0 is
// the bottom row of the image (the file's last row). Bilinear weights keep 8
// sub-texel bits (D3D11's minimum); texel centres sit at half-integers.
#pragma once

#include <cstdint>

#include "spanlight/pixel_inline.hpp"
#include "spanlight/prepared_scene.hpp"

namespace spanlight {

struct Rgb8 {
  std::uint8_t r, g, b;
};

// Index along one axis after wrapping; -1 means "outside, black" (border).
[[gnu::always_inline]] constexpr std::int32_t wrap_index(std::int32_t i, std::int32_t size, Wrap wrap) {
  switch (wrap) {
    case Wrap::repeat: return i & (size - 1);  // power-of-two sizes only (validated by the scene loader)
    case Wrap::clamp: return i < 0 ? 0 : (i >= size ? size - 1 : i);
    case Wrap::border: return (i < 0 || i >= size) ? -1 : i;
  }
  return -1;
}

struct Texel16 {
  std::uint32_t r, g, b;  // 8-bit channels scaled by a weight (sum of weights 2^16 at most)
};

// Row start of texel row `y_from_bottom` (already wrapped into the image).
SPANLIGHT_PIXEL_INLINE const std::uint8_t* texel_row(const TextureData& tex, std::int32_t y_from_bottom) {
  return tex.rgb + static_cast<std::uint32_t>(tex.height - 1 - y_from_bottom) * tex.width * 3u;
}

SPANLIGHT_PIXEL_INLINE Rgb8 fetch(const TextureData& tex, std::int32_t x, std::int32_t y_from_bottom, Wrap wrap) {
  const std::int32_t xi = wrap_index(x, tex.width, wrap);
  const std::int32_t yi = wrap_index(y_from_bottom, tex.height, wrap);
  if (xi < 0 || yi < 0) return {0, 0, 0};
  const std::uint8_t* p = texel_row(tex, yi) + static_cast<std::uint32_t>(xi) * 3u;
  return {p[0], p[1], p[2]};
}

// Sub-texel weight in [0, 256) from a coordinate with `frac` fraction bits.
[[gnu::always_inline]] constexpr std::uint32_t weight8(std::int32_t coord, int frac) {
  return frac >= 8 ? (static_cast<std::uint32_t>(coord) >> (frac - 8)) & 255u
                   : (static_cast<std::uint32_t>(coord) << (8 - frac)) & 255u;
}

SPANLIGHT_PIXEL_INLINE Rgb8 sample_nearest(const TextureData& tex, std::int32_t u, std::int32_t v, int frac, Wrap wrap) {
  return fetch(tex, u >> frac, v >> frac, wrap);
}

// The four-texel blend before rounding: 8-bit channels times weights summing
// to 2^16. Projectors keep these bits through the colour multiply. W is the
// wrap mode when the caller knows it (projectors: border; a run's texture).
template <Wrap W>
SPANLIGHT_PIXEL_INLINE Texel16 sample16_bilinear_as(const TextureData& tex, std::int32_t u, std::int32_t v, int frac) {
  const std::int32_t half = frac > 0 ? (1 << (frac - 1)) : 0;  // move to texel centres
  const std::int32_t x = u - half, y = v - half;
  std::int32_t x0 = x >> frac, y0 = y >> frac;
  const std::uint32_t fx = weight8(x, frac), fy = weight8(y, frac);
  std::int32_t x1 = x0 + 1, y1 = y0 + 1;
  Rgb8 c00, c10, c01, c11;
  if (W != Wrap::border || (x0 >= 0 && y0 >= 0 && x1 < tex.width && y1 < tex.height)) {
    // Fast path: wrap each axis once, then four direct reads.
    x0 = wrap_index(x0, tex.width, W);
    x1 = wrap_index(x1, tex.width, W);
    y0 = wrap_index(y0, tex.height, W);
    y1 = wrap_index(y1, tex.height, W);
    const std::uint8_t* row0 = texel_row(tex, y0);
    const std::uint8_t* row1 = texel_row(tex, y1);
    const std::uint32_t i0 = static_cast<std::uint32_t>(x0) * 3u, i1 = static_cast<std::uint32_t>(x1) * 3u;
    c00 = {row0[i0], row0[i0 + 1], row0[i0 + 2]};
    c10 = {row0[i1], row0[i1 + 1], row0[i1 + 2]};
    c01 = {row1[i0], row1[i0 + 1], row1[i0 + 2]};
    c11 = {row1[i1], row1[i1 + 1], row1[i1 + 2]};
  } else {
    // Border at the image's edge: texels outside are black, one check each.
    c00 = fetch(tex, x0, y0, W);
    c10 = fetch(tex, x1, y0, W);
    c01 = fetch(tex, x0, y1, W);
    c11 = fetch(tex, x1, y1, W);
  }
  const std::uint32_t w00 = (256 - fx) * (256 - fy), w10 = fx * (256 - fy), w01 = (256 - fx) * fy, w11 = fx * fy;
  auto blend = [&](std::uint8_t a, std::uint8_t b, std::uint8_t c, std::uint8_t d) {
    return a * w00 + b * w10 + c * w01 + d * w11;
  };
  return {blend(c00.r, c10.r, c01.r, c11.r), blend(c00.g, c10.g, c01.g, c11.g), blend(c00.b, c10.b, c01.b, c11.b)};
}

// The same with the wrap mode known at run time only: out of line, since
// inlined at every call site it makes the span loops spill more than the call costs.
inline Texel16 sample16_bilinear(const TextureData& tex, std::int32_t u, std::int32_t v, int frac, Wrap wrap) {
  switch (wrap) {
    case Wrap::repeat: return sample16_bilinear_as<Wrap::repeat>(tex, u, v, frac);
    case Wrap::clamp: return sample16_bilinear_as<Wrap::clamp>(tex, u, v, frac);
    case Wrap::border: break;
  }
  return sample16_bilinear_as<Wrap::border>(tex, u, v, frac);
}

SPANLIGHT_PIXEL_INLINE Rgb8 round_texel(const Texel16& t) {
  auto round8 = [](std::uint32_t c) { return static_cast<std::uint8_t>((c + 32768u) >> 16); };
  return {round8(t.r), round8(t.g), round8(t.b)};
}

// A repeat-wrapped texture with what its bilinear fetch needs worked out once
// per run (the modulate pass's fast path): masks, the row stride, where row 0
// (the image's last) starts, and at least 8 sub-texel bits, so the weight needs no branch.
struct RepeatTexture {
  const std::uint8_t* row0;  // texel row 0 from the bottom
  std::uint32_t stride;      // bytes per row
  std::uint32_t x_mask, y_mask;
  int frac, weight_shift;    // frac >= 8; weight_shift = frac - 8
  std::int32_t half;         // half a texel: texel centres sit at half-integers
  static constexpr bool fits(int uv_frac_bits) { return uv_frac_bits >= 8; }
  RepeatTexture(const TextureData& tex, int uv_frac_bits)
      : row0(tex.rgb + static_cast<std::uint32_t>(tex.height - 1) * tex.width * 3u),
        stride(tex.width * 3u),
        x_mask(tex.width - 1u),
        y_mask(tex.height - 1u),
        frac(uv_frac_bits),
        weight_shift(uv_frac_bits - 8),
        half(std::int32_t{1} << (uv_frac_bits - 1)) {}
};

// sample16_bilinear_as<Wrap::repeat> rounded to 8 bits, to the bit, out of line for the run
// loop and returned packed in one register (0x00BBGGRR) rather than as a struct through memory.
[[gnu::noinline]] inline std::uint32_t sample_bilinear_packed(const RepeatTexture& tex, std::int32_t u, std::int32_t v) {
  const std::int32_t x = u - tex.half, y = v - tex.half;
  const std::int32_t x0 = x >> tex.frac, y0 = y >> tex.frac;
  const std::uint32_t fx = (static_cast<std::uint32_t>(x) >> tex.weight_shift) & 255u;
  const std::uint32_t fy = (static_cast<std::uint32_t>(y) >> tex.weight_shift) & 255u;
  const std::uint32_t i0 = (static_cast<std::uint32_t>(x0) & tex.x_mask) * 3u;
  const std::uint32_t i1 = (static_cast<std::uint32_t>(x0 + 1) & tex.x_mask) * 3u;
  const std::uint8_t* row0 = tex.row0 - (static_cast<std::uint32_t>(y0) & tex.y_mask) * tex.stride;
  const std::uint8_t* row1 = tex.row0 - (static_cast<std::uint32_t>(y0 + 1) & tex.y_mask) * tex.stride;
  const std::uint32_t w00 = (256 - fx) * (256 - fy), w10 = fx * (256 - fy), w01 = (256 - fx) * fy, w11 = fx * fy;
  std::uint32_t packed = 0;
#pragma GCC unroll 3
  for (std::uint32_t c = 0; c < 3; ++c) {
    const std::uint32_t blend = row0[i0 + c] * w00 + row0[i1 + c] * w10 + row1[i0 + c] * w01 + row1[i1 + c] * w11;
    packed |= ((blend + 32768u) >> 16) << (8 * c);
  }
  return packed;
}
SPANLIGHT_PIXEL_INLINE Rgb8 unpack_rgb(std::uint32_t packed) {
  return {static_cast<std::uint8_t>(packed), static_cast<std::uint8_t>(packed >> 8), static_cast<std::uint8_t>(packed >> 16)};
}

SPANLIGHT_PIXEL_INLINE Rgb8 sample_bilinear(const TextureData& tex, std::int32_t u, std::int32_t v, int frac, Wrap wrap) {
  return round_texel(sample16_bilinear(tex, u, v, frac, wrap));
}

// A projector's image is always read with border; out of line like sample16_bilinear.
inline Texel16 sample16_bilinear_border(const TextureData& tex, std::int32_t u, std::int32_t v, int frac) {
  return sample16_bilinear_as<Wrap::border>(tex, u, v, frac);
}

// Texel channels times 2^16 (unrounded when bilinear), border wrap: a projector's image.
template <bool Bilinear>
SPANLIGHT_PIXEL_INLINE Texel16 sample16_border(const TextureData& tex, std::int32_t u, std::int32_t v, int frac) {
  if constexpr (Bilinear) {
    if (tex.filter == Filter::bilinear) return sample16_bilinear_border(tex, u, v, frac);
  }
  const Rgb8 t = sample_nearest(tex, u, v, frac, Wrap::border);
  return {std::uint32_t{t.r} << 16, std::uint32_t{t.g} << 16, std::uint32_t{t.b} << 16};
}

template <bool Bilinear>
SPANLIGHT_PIXEL_INLINE Rgb8 sample(const TextureData& tex, std::int32_t u, std::int32_t v, int frac, Wrap wrap) {
  if constexpr (Bilinear) {
    if (tex.filter == Filter::bilinear) return sample_bilinear(tex, u, v, frac, wrap);
  }
  return sample_nearest(tex, u, v, frac, wrap);
}

}  // namespace spanlight
