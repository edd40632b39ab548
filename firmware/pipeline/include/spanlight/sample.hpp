// Stage 5, sampling: nearest and bilinear texel fetches with repeat, clamp and
// border. Coordinates arrive in texels with `frac` sub-texel bits; t = 0 is
// the bottom row of the image (the file's last row). Bilinear weights keep 8
// sub-texel bits (D3D11's minimum); texel centres sit at half-integers.
#pragma once

#include <cstdint>

#include "spanlight/prepared_scene.hpp"

namespace spanlight {

struct Rgb8 {
  std::uint8_t r, g, b;
};

// Index along one axis after wrapping; -1 means "outside, black" (border).
constexpr std::int32_t wrap_index(std::int32_t i, std::int32_t size, Wrap wrap) {
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

inline Rgb8 fetch(const TextureData& tex, std::int32_t x, std::int32_t y_from_bottom, Wrap wrap) {
  const std::int32_t xi = wrap_index(x, tex.width, wrap);
  const std::int32_t yi = wrap_index(y_from_bottom, tex.height, wrap);
  if (xi < 0 || yi < 0) return {0, 0, 0};
  const std::uint8_t* p = tex.rgb + (static_cast<std::uint32_t>(tex.height - 1 - yi) * tex.width + static_cast<std::uint32_t>(xi)) * 3u;
  return {p[0], p[1], p[2]};
}

// Sub-texel weight in [0, 256) from a coordinate with `frac` fraction bits.
constexpr std::uint32_t weight8(std::int32_t coord, int frac) {
  return frac >= 8 ? (static_cast<std::uint32_t>(coord) >> (frac - 8)) & 255u
                   : (static_cast<std::uint32_t>(coord) << (8 - frac)) & 255u;
}

inline Rgb8 sample_nearest(const TextureData& tex, std::int32_t u, std::int32_t v, int frac, Wrap wrap) {
  return fetch(tex, u >> frac, v >> frac, wrap);
}

inline Rgb8 sample_bilinear(const TextureData& tex, std::int32_t u, std::int32_t v, int frac, Wrap wrap) {
  const std::int32_t half = frac > 0 ? (1 << (frac - 1)) : 0;  // move to texel centres
  const std::int32_t x = u - half, y = v - half;
  const std::int32_t x0 = x >> frac, y0 = y >> frac;
  const std::uint32_t fx = weight8(x, frac), fy = weight8(y, frac);
  const Rgb8 c00 = fetch(tex, x0, y0, wrap), c10 = fetch(tex, x0 + 1, y0, wrap);
  const Rgb8 c01 = fetch(tex, x0, y0 + 1, wrap), c11 = fetch(tex, x0 + 1, y0 + 1, wrap);
  const std::uint32_t w00 = (256 - fx) * (256 - fy), w10 = fx * (256 - fy), w01 = (256 - fx) * fy, w11 = fx * fy;
  // Sum of weights is 2^16; round to nearest on the way back to 8 bits.
  auto blend = [&](std::uint8_t a, std::uint8_t b, std::uint8_t c, std::uint8_t d) {
    return static_cast<std::uint8_t>((a * w00 + b * w10 + c * w01 + d * w11 + 32768u) >> 16);
  };
  return {blend(c00.r, c10.r, c01.r, c11.r), blend(c00.g, c10.g, c01.g, c11.g), blend(c00.b, c10.b, c01.b, c11.b)};
}

template <bool Bilinear>
inline Rgb8 sample(const TextureData& tex, std::int32_t u, std::int32_t v, int frac, Wrap wrap) {
  if constexpr (Bilinear) {
    if (tex.filter == Filter::bilinear) return sample_bilinear(tex, u, v, frac, wrap);
  }
  return sample_nearest(tex, u, v, frac, wrap);
}

}  // namespace spanlight
