// Stage 4a, texture sampling: nearest and bilinear fetches from the baked
// layout (scene.hpp: 0x00RRGGBB words, rows from the bottom, a one-texel frame
// that answers for the wrap mode). Coordinates arrive as the span walk steps
// them (walk.hpp, StepScale): for a repeating texture as a fraction of its size
// in 32 bits (the integer texel is the top log2(size) bits, and wrapping is
// the repeat), else in texels with `frac` sub-texel bits (8..16). For bilinear
// filtering they already point half a texel back (texel centres sit at
// half-integers). Bilinear weights keep 8 sub-texel bits (D3D11's minimum) and
// are rounded once, exactly:
//
//   c = round(sum c_ij w_ij / 2^16),  w_00 = (256 - fx)(256 - fy), ..., w_11 = fx fy.
#pragma once

#include <algorithm>
#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/lanes.hpp"
#include "spanlight/4_pixel/colour.hpp"
#include "spanlight/inline.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

// One level of a texture as a sampler reads it, with the per-object uv format.
struct TexelGrid {
  const std::uint32_t* texels;  // texel (0, 0)
  std::int32_t stride;          // words from a row to the next
  std::int32_t width, height;
  int frac;                     // texels * 2^frac coordinates (not repeating): 8..16
  int x_shift, y_shift;         // repeating coordinates: 32 - log2 of the width, of the height
};

constexpr int log2_of_power_of_two(std::uint32_t x) { return 31 - fixedpoint::clz32(x); }

constexpr TexelGrid texel_grid(const TextureLevel& level, int frac) {
  return {level.texels, level.stride, level.width, level.height, frac, 32 - log2_of_power_of_two(level.width),
          32 - log2_of_power_of_two(level.height)};
}

// ---- bilinear -----------------------------------------------------------------

// A footprint: its four texels (t_xy, x to the right, y up a row) and the weights of the right and upper ones.
struct Taps {
  std::uint32_t t00, t10, t01, t11;
  std::uint32_t fx, fy;  // 0..255
};

// The exact blend of four texels, all three channels. Red and blue share 16-bit
// lanes (0x00RR00BB): a horizontal blend h = c0 (256 - fx) + c1 fx is below
// 2^16 in each lane. The vertical blend of h needs 24 bits, so h is split into
// its high and low bytes, each blended in the lanes (again below 2^16):
//   S = 256 A + B,  A = sum hi(h) w_y,  B = sum lo(h) w_y,
//   round(S / 2^16) = (A + floor(B / 256) + 128) >> 8,
// and A + B/256 <= S/256 <= 255 * 256, so the lanes never carry into each other.
// Green blends in one word (below 2^24), a column's two texels paired in lanes (one blend for both rows).
struct BilinearSums {
  std::uint32_t a_rb, b_rb;  // A and B above, red and blue lanes
  std::uint32_t g;           // sum g_ij w_ij, < 2^24
};

// c0 (256 - f) + c1 f for lanes c0, c1 (0 <= f <= 256), as 256 c0 + (c1 - c0) f: one product.
// A lane of c1 - c0 may borrow from the next, but every lane of the result lies in [0, 2^16)
// (or one lane in [0, 2^24)), so the word modulo 2^32 is exactly the lanes' sums.
[[gnu::always_inline]] constexpr std::uint32_t lerp_lanes(std::uint32_t c0, std::uint32_t c1, std::uint32_t f) {
  return (c0 << 8) + (c1 - c0) * f;
}

// Every blend on lanes of 32-bit words. Red and blue of a row share a word; green travels as a
// vector over the two rows ((t >> 8) | (t' << 8)) & 0x00FF00FF (top in lane 0, bottom in lane 1;
// byte 3 of a texel is zero), so one horizontal blend serves both rows, and the vertical blend is its two lanes'.
[[gnu::always_inline]] constexpr BilinearSums bilinear_sums(const Taps& t) {
  constexpr std::uint32_t m = 0x00FF00FFu;
  const std::uint32_t rb_top = lerp_lanes(t.t00 & m, t.t10 & m, t.fx), rb_bottom = lerp_lanes(t.t01 & m, t.t11 & m, t.fx);
  const std::uint32_t g_rows = lerp_lanes(((t.t00 >> 8) | (t.t01 << 8)) & m, ((t.t10 >> 8) | (t.t11 << 8)) & m, t.fx);
  return {lerp_lanes((rb_top >> 8) & m, (rb_bottom >> 8) & m, t.fy), lerp_lanes(rb_top & m, rb_bottom & m, t.fy),
          lerp_lanes(g_rows & 0xFFFFu, g_rows >> 16, t.fy)};
}

[[gnu::always_inline]] inline Colour round_sums(const BilinearSums& s) {
  return {fixedpoint::bytes_1_3(fixedpoint::add_bytes_1_3(s.a_rb, s.b_rb) + 0x00800080u), (s.g + 0x8000u) >> 16};
}

// Each channel's sum S before rounding (8-bit level * 2^16): a projector keeps these
// bits through its colour multiply, and trilinear through its mix.
struct Texel16 {
  std::uint32_t r, g, b;
};
[[gnu::always_inline]] inline Texel16 unrounded(const BilinearSums& s) {
  return {((s.a_rb >> 16) << 8) + (s.b_rb >> 16), s.g, ((s.a_rb & 0xFFFFu) << 8) + (s.b_rb & 0xFFFFu)};
}

// The same sums from dual signed multiply-adds (smlad), each channel's vertical blend one
// instruction. A row's lane h (< 2^16) less 2^15 is a signed halfword (h ^ 0x8000), the two
// rows' pair is dotted with (256 - fy, fy), and the accumulator puts the bias back with `plus`:
//   sum (h_i - 2^15) w_i + 2^23 + plus = S + plus  (w sums to 256); S + plus < 2^24 + 2^15 fits an int32.
// The horizontal blends are c0 (256 - fx) + c1 fx in lanes, green paired by columns.
[[gnu::always_inline]] inline Texel16 bilinear_dot_sums(const Taps& t, std::uint32_t plus) {
  using fixedpoint::bytes_0_2, fixedpoint::pair_byte_1;
  constexpr std::uint32_t bias = 0x80008000u;
  const std::uint32_t ifx = 256u - t.fx;
  auto row = [&](std::uint32_t c0, std::uint32_t c1) SPANLIGHT_LAMBDA_INLINE_ATTR { return (c0 * ifx + c1 * t.fx) ^ bias; };
  const std::uint32_t rb_top = row(bytes_0_2(t.t00), bytes_0_2(t.t10)), rb_bottom = row(bytes_0_2(t.t01), bytes_0_2(t.t11));
  const std::uint32_t g_rows = row(pair_byte_1(t.t00, t.t01), pair_byte_1(t.t10, t.t11));  // top row in lane 0
  const std::uint32_t wy = (256u - t.fy) | (t.fy << 16);
  const auto acc = static_cast<std::int32_t>((1u << 23) + plus);
  auto dot = [&](std::uint32_t rows) SPANLIGHT_LAMBDA_INLINE_ATTR { return static_cast<std::uint32_t>(fixedpoint::dot_signed_lanes_plus(rows, wy, acc)); };
  const std::uint32_t r = dot(fixedpoint::high_lanes(rb_top, rb_bottom)), b = dot(fixedpoint::low_lanes(rb_top, rb_bottom));
  return {r, dot(g_rows), b};
}

// A footprint's colour rounded, and its sums unrounded, each in the form that costs fewer
// instructions: the dual multiply-adds where the core has them, the lanes elsewhere (measured
// on Cortex-M7 with tools/qemu_icount/measure_elf.sh: textured_room -7 %, its trilinear twin -11 %,
// horizon -8 %). sample_test and firmware.blend_check check
// that both forms give the scalar sums on every weight.
[[gnu::always_inline]] inline Colour bilinear_colour(const Taps& t) {
#if FIXEDPOINT_HAS_DSP
  const Texel16 s = bilinear_dot_sums(t, 1u << 15);  // round(S / 2^16) = (S + 2^15) >> 16
  return {fixedpoint::high_lanes(s.b, s.r), s.g >> 16};  // (r & 0xFFFF0000) | b >> 16: each below 256
#else
  return round_sums(bilinear_sums(t));
#endif
}
[[gnu::always_inline]] inline Texel16 bilinear_texel16(const Taps& t) {
#if FIXEDPOINT_HAS_DSP
  return bilinear_dot_sums(t, 0);
#else
  return unrounded(bilinear_sums(t));
#endif
}

// The taps at texel p (row stride in words) with weights fx, fy.
[[gnu::always_inline]] inline Taps taps_at(const std::uint32_t* p, std::int32_t stride, std::uint32_t fx, std::uint32_t fy) {
  return {p[0], p[1], p[stride], p[stride + 1], fx, fy};
}

// Repeating: x0 is the top bits, the weight the next 8 (x_shift >= 20 for sizes up to 4096).
[[gnu::always_inline]] inline Colour bilinear_repeat_at(const std::uint32_t* texels, std::int32_t stride, int x_shift,
                                                     int y_shift, std::uint32_t x, std::uint32_t y) {
  const std::uint32_t x0 = x >> x_shift, y0 = y >> y_shift;
  const std::uint32_t fx = (x >> (x_shift - 8)) & 255u, fy = (y >> (y_shift - 8)) & 255u;
  return bilinear_colour(taps_at(texels + static_cast<std::int32_t>(y0) * stride + static_cast<std::int32_t>(x0), stride, fx, fy));
}
[[gnu::always_inline]] inline Colour bilinear_repeat(const TexelGrid& g, std::uint32_t x, std::uint32_t y) {
  return bilinear_repeat_at(g.texels, g.stride, g.x_shift, g.y_shift, x, y);
}

// The same for a size known at compile time (Features::repeat_sizes): shifts and stride are constants.
template <int WidthLog2, int HeightLog2>
struct BilinearRepeatOfSize {
  const std::uint32_t* texels;
  [[gnu::always_inline]] Colour operator()(std::uint32_t x, std::uint32_t y) const {
    return bilinear_repeat_at(texels, (std::int32_t{1} << WidthLog2) + 2 * texture_frame, 32 - WidthLog2, 32 - HeightLog2, x, y);
  }
};
template <int WidthLog2, int HeightLog2>
struct NearestRepeatOfSize {
  const std::uint32_t* texels;
  [[gnu::always_inline]] Colour operator()(std::uint32_t x, std::uint32_t y) const {
    return colour_of(texels[static_cast<std::int32_t>(y >> (32 - HeightLog2)) * ((std::int32_t{1} << WidthLog2) + 2 * texture_frame) +
                  static_cast<std::int32_t>(x >> (32 - WidthLog2))]);
  }
};

// Clamp to edge: beyond the centres of the outer texels the edge texel alone
// (x0 in [0, width - 1]; the frame holds column `width` for the zero weight).
[[gnu::always_inline]] inline Taps bilinear_clamp_taps(const TexelGrid& g, std::int32_t x, std::int32_t y) {
  const std::int32_t x_max = (g.width - 1) << g.frac, y_max = (g.height - 1) << g.frac;
  x = std::clamp(x, std::int32_t{0}, x_max);
  y = std::clamp(y, std::int32_t{0}, y_max);
  const int weight_shift = g.frac - 8;
  return taps_at(g.texels + (y >> g.frac) * g.stride + (x >> g.frac), g.stride, (static_cast<std::uint32_t>(x) >> weight_shift) & 255u,
                 (static_cast<std::uint32_t>(y) >> weight_shift) & 255u);
}
[[gnu::always_inline]] inline Colour bilinear_clamp(const TexelGrid& g, std::int32_t x, std::int32_t y) {
  return bilinear_colour(bilinear_clamp_taps(g, x, y));
}

// Border on an object's texture, where the coordinate may lie anywhere: texels
// outside the image are black. Out of line: rare, and bulky inlined.
[[gnu::noinline]] inline Taps bilinear_border_taps(const TexelGrid& g, std::int32_t x, std::int32_t y) {
  const std::int32_t x0 = x >> g.frac, y0 = y >> g.frac;
  auto at = [&](std::int32_t xi, std::int32_t yi) -> std::uint32_t {
    return xi < 0 || yi < 0 || xi >= g.width || yi >= g.height ? 0u : g.texels[yi * g.stride + xi];
  };
  const int weight_shift = g.frac - 8;
  return {at(x0, y0), at(x0 + 1, y0), at(x0, y0 + 1), at(x0 + 1, y0 + 1), (static_cast<std::uint32_t>(x) >> weight_shift) & 255u,
          (static_cast<std::uint32_t>(y) >> weight_shift) & 255u};
}
[[gnu::always_inline]] inline Colour bilinear_border(const TexelGrid& g, std::int32_t x, std::int32_t y) {
  return bilinear_colour(bilinear_border_taps(g, x, y));
}

// ---- nearest ------------------------------------------------------------------

[[gnu::always_inline]] inline Colour nearest_repeat(const TexelGrid& g, std::uint32_t x, std::uint32_t y) {
  return colour_of(g.texels[static_cast<std::int32_t>(y >> g.y_shift) * g.stride + static_cast<std::int32_t>(x >> g.x_shift)]);
}

template <Wrap W>
[[gnu::always_inline]] inline Colour nearest(const TexelGrid& g, std::int32_t u, std::int32_t v) {
  std::int32_t x = u >> g.frac, y = v >> g.frac;
  if constexpr (W == Wrap::clamp) {
    x = std::clamp(x, std::int32_t{0}, g.width - 1);
    y = std::clamp(y, std::int32_t{0}, g.height - 1);
  } else {
    if (x < 0 || y < 0 || x >= g.width || y >= g.height) return black;
  }
  return colour_of(g.texels[y * g.stride + x]);
}

// ---- a projector's image --------------------------------------------------------

// The image at (s/q, t/q) in [0, 1]^2 (the caller has tested it), in texels with 8
// fraction bits, unrounded when bilinear. Its frame is black (border): from a
// coordinate in [0, size], x0 = floor(x - 1/2) lies in [-1, size - 1].
[[gnu::always_inline]] inline Texel16 projector_texel(const TextureData& image, std::int32_t x8, std::int32_t y8, bool bilinear_ok) {
  const TextureLevel& level = image.levels[0];
  if (bilinear_ok && image.filter != Filter::nearest) {
    const std::int32_t x = x8 - 128, y = y8 - 128;
    return bilinear_texel16(taps_at(level.texels + (y >> 8) * level.stride + (x >> 8), level.stride, static_cast<std::uint32_t>(x) & 255u,
                                    static_cast<std::uint32_t>(y) & 255u));
  }
  const Colour c = nearest<Wrap::border>(texel_grid(level, 8), x8, y8);
  return {red(c) << 16, green(c) << 16, blue(c) << 16};
}

}  // namespace spanlight
