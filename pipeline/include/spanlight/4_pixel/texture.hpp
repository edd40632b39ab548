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

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/lanes.hpp"
#include "spanlight/4_pixel/colour.hpp"
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

// The exact blend of four texels, all three channels. Red and blue share 16-bit
// lanes (0x00RR00BB): a horizontal blend h = c0 (256 - fx) + c1 fx is below
// 2^16 in each lane. The vertical blend of h needs 24 bits, so h is split into
// its high and low bytes, each blended in the lanes (again below 2^16):
//   S = 256 A + B,  A = sum hi(h) w_y,  B = sum lo(h) w_y,
//   round(S / 2^16) = (A + floor(B / 256) + 128) >> 8,
// and A + B/256 <= S/256 <= 255 * 256, so the lanes never carry into each other.
// Green blends in one word (below 2^24), its texels paired in lanes: a column's two (one
// blend for both rows), or in the row form below a row's two (one dot product).
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

// Every blend on lanes of 32-bit words, on every target. Red and blue of a row share a word;
// green travels as a vector over the two rows ((t >> 8) | (t' << 8)) & 0x00FF00FF (top in lane 0, bottom in lane 1; byte 3 of a texel is
// zero), so one horizontal blend serves both rows, and the vertical blend is its two lanes'.
[[gnu::always_inline]] constexpr BilinearSums bilinear_sums(std::uint32_t t00, std::uint32_t t10, std::uint32_t t01,
                                                            std::uint32_t t11, std::uint32_t fx, std::uint32_t fy) {
  constexpr std::uint32_t m = 0x00FF00FFu;
  const std::uint32_t rb_top = lerp_lanes(t00 & m, t10 & m, fx), rb_bottom = lerp_lanes(t01 & m, t11 & m, fx);
  const std::uint32_t g_rows = lerp_lanes(((t00 >> 8) | (t01 << 8)) & m, ((t10 >> 8) | (t11 << 8)) & m, fx);
  return {lerp_lanes((rb_top >> 8) & m, (rb_bottom >> 8) & m, fy), lerp_lanes(rb_top & m, rb_bottom & m, fy),
          lerp_lanes(g_rows & 0xFFFFu, g_rows >> 16, fy)};
}

// Which form runs fewer instructions depends on what else the pixel loop keeps in registers
// (measured on Cortex-M7 with tools/qemu_icount/measure_elf.sh): the lane form in an object's
// sampler (textured_room -5.7 %, mesh_bear -2.4 %), the row form in a projector's image
// (horizon -2.3 %, spot_shadow -1.4 %). Both give the same sums on every input.
#if FIXEDPOINT_HAS_DSP
// With lane instructions, a second form of the same sums, a row at a time:
// h = c0 (256 - fx) + c1 fx, red and blue in their lanes, the row's two greens as a pair through one dual multiply-add (uxtb16, uxtab16, smuad).
struct RowWeights {
  std::uint32_t ifx, fx, pair;  // pair = ifx | fx << 16
};
[[gnu::always_inline]] inline RowWeights row_weights(std::uint32_t fx) { return {256u - fx, fx, (256u - fx) | (fx << 16)}; }

struct RowBlend {
  std::uint32_t rb, g;  // each lane < 2^16; g < 2^16
};
[[gnu::always_inline]] inline RowBlend row_blend(std::uint32_t t0, std::uint32_t t1, const RowWeights& w) {
  using fixedpoint::bytes_0_2;
  return {bytes_0_2(t0) * w.ifx + bytes_0_2(t1) * w.fx, fixedpoint::dot_lanes(fixedpoint::pair_byte_1(t0, t1), w.pair)};
}

// The vertical blend of the two rows.
[[gnu::always_inline]] inline BilinearSums column_blend(const RowBlend& top, const RowBlend& bottom, std::uint32_t fy) {
  using fixedpoint::bytes_0_2, fixedpoint::bytes_1_3;
  const std::uint32_t ify = 256u - fy;
  const std::uint32_t a = bytes_1_3(top.rb) * ify + bytes_1_3(bottom.rb) * fy;
  const std::uint32_t b = bytes_0_2(top.rb) * ify + bytes_0_2(bottom.rb) * fy;
  return {a, b, top.g * ify + bottom.g * fy};
}

[[gnu::always_inline]] inline BilinearSums bilinear_sums_by_rows(std::uint32_t t00, std::uint32_t t10, std::uint32_t t01,
                                                                 std::uint32_t t11, std::uint32_t fx, std::uint32_t fy) {
  const RowWeights w = row_weights(fx);
  return column_blend(row_blend(t00, t10, w), row_blend(t01, t11, w), fy);
}
#else
[[gnu::always_inline]] constexpr BilinearSums bilinear_sums_by_rows(std::uint32_t t00, std::uint32_t t10, std::uint32_t t01,
                                                                    std::uint32_t t11, std::uint32_t fx, std::uint32_t fy) {
  return bilinear_sums(t00, t10, t01, t11, fx, fy);
}
#endif

[[gnu::always_inline]] inline Colour round_sums(const BilinearSums& s) {
  return {fixedpoint::bytes_1_3(fixedpoint::add_bytes_1_3(s.a_rb, s.b_rb) + 0x00800080u), (s.g + 0x8000u) >> 16};
}

// Each channel's sum before rounding (8-bit level * 2^16): a projector keeps these
// bits through its colour multiply.
struct Texel16 {
  std::uint32_t r, g, b;
};
[[gnu::always_inline]] inline Texel16 unrounded(const BilinearSums& s) {
  return {((s.a_rb >> 16) << 8) + (s.b_rb >> 16), s.g, ((s.a_rb & 0xFFFFu) << 8) + (s.b_rb & 0xFFFFu)};
}

// Where the top-left texel of a bilinear footprint is, and the weights.
struct Footprint {
  const std::uint32_t* p;  // texel (x0, y0)
  std::uint32_t fx, fy;
};

[[gnu::always_inline]] inline BilinearSums footprint_sums(const Footprint& f, std::int32_t stride) {
  return bilinear_sums(f.p[0], f.p[1], f.p[stride], f.p[stride + 1], f.fx, f.fy);
}

// Repeating: x0 is the top bits, the weight the next 8 (x_shift >= 20 for sizes up to 4096).
[[gnu::always_inline]] inline Colour bilinear_repeat_at(const std::uint32_t* texels, std::int32_t stride, int x_shift,
                                                     int y_shift, std::uint32_t x, std::uint32_t y) {
  const std::uint32_t x0 = x >> x_shift, y0 = y >> y_shift;
  const std::uint32_t fx = (x >> (x_shift - 8)) & 255u, fy = (y >> (y_shift - 8)) & 255u;
  return round_sums(footprint_sums({texels + static_cast<std::int32_t>(y0) * stride + static_cast<std::int32_t>(x0), fx, fy}, stride));
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
[[gnu::always_inline]] inline BilinearSums bilinear_clamp_sums(const TexelGrid& g, std::int32_t x, std::int32_t y) {
  const std::int32_t x_max = (g.width - 1) << g.frac, y_max = (g.height - 1) << g.frac;
  x = x < 0 ? 0 : (x > x_max ? x_max : x);
  y = y < 0 ? 0 : (y > y_max ? y_max : y);
  const int weight_shift = g.frac - 8;
  return footprint_sums({g.texels + (y >> g.frac) * g.stride + (x >> g.frac),
                         (static_cast<std::uint32_t>(x) >> weight_shift) & 255u,
                         (static_cast<std::uint32_t>(y) >> weight_shift) & 255u}, g.stride);
}
[[gnu::always_inline]] inline Colour bilinear_clamp(const TexelGrid& g, std::int32_t x, std::int32_t y) {
  return round_sums(bilinear_clamp_sums(g, x, y));
}

// Border on an object's texture, where the coordinate may lie anywhere: texels
// outside the image are black. Out of line: rare, and bulky inlined.
[[gnu::noinline]] inline BilinearSums bilinear_border_sums(const TexelGrid& g, std::int32_t x, std::int32_t y) {
  const std::int32_t x0 = x >> g.frac, y0 = y >> g.frac;
  auto at = [&](std::int32_t xi, std::int32_t yi) -> std::uint32_t {
    return xi < 0 || yi < 0 || xi >= g.width || yi >= g.height ? 0u : g.texels[yi * g.stride + xi];
  };
  const int weight_shift = g.frac - 8;
  return bilinear_sums(at(x0, y0), at(x0 + 1, y0), at(x0, y0 + 1), at(x0 + 1, y0 + 1),
                       (static_cast<std::uint32_t>(x) >> weight_shift) & 255u,
                       (static_cast<std::uint32_t>(y) >> weight_shift) & 255u);
}
[[gnu::always_inline]] inline Colour bilinear_border(const TexelGrid& g, std::int32_t x, std::int32_t y) {
  return round_sums(bilinear_border_sums(g, x, y));
}

// ---- nearest ------------------------------------------------------------------

[[gnu::always_inline]] inline Colour nearest_repeat(const TexelGrid& g, std::uint32_t x, std::uint32_t y) {
  return colour_of(g.texels[static_cast<std::int32_t>(y >> g.y_shift) * g.stride + static_cast<std::int32_t>(x >> g.x_shift)]);
}

template <Wrap W>
[[gnu::always_inline]] inline Colour nearest(const TexelGrid& g, std::int32_t u, std::int32_t v) {
  std::int32_t x = u >> g.frac, y = v >> g.frac;
  if constexpr (W == Wrap::clamp) {
    x = x < 0 ? 0 : (x >= g.width ? g.width - 1 : x);
    y = y < 0 ? 0 : (y >= g.height ? g.height - 1 : y);
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
    const std::uint32_t* p = level.texels + (y >> 8) * level.stride + (x >> 8);
    return unrounded(bilinear_sums_by_rows(p[0], p[1], p[level.stride], p[level.stride + 1], static_cast<std::uint32_t>(x) & 255u,
                                           static_cast<std::uint32_t>(y) & 255u));
  }
  const Colour c = nearest<Wrap::border>(texel_grid(level, 8), x8, y8);
  return {red(c) << 16, green(c) << 16, blue(c) << 16};
}

}  // namespace spanlight
