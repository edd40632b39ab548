// Stage 1c, the perspective divide: clip space to snapped window coordinates.
// One reciprocal per vertex (8-bit table, two Newton steps: relative error
// below 2^-28.9, docs/reciprocal.md — as good as a 12-bit table and 7.5 KB
// less flash), so a 4096-px-wide window lands within 2^-8 subpixel before the
// rounding to 1/256 px.
#pragma once

#include <algorithm>
#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/reciprocal.hpp"
#include "spanlight/1_vertex/transform.hpp"

namespace spanlight {

inline constexpr int subpixel_bits = 8;  // D3D11's 8 sub-pixel bits
inline constexpr int depth_frac_bits = 30;  // window depth, Q1.30

struct ScreenVertex {
  std::int32_t x, y;  // window position in 1/256 px, y down (row 0 at the top)
  std::int32_t z;     // window depth (z/w + 1)/2, Q1.30
  std::uint32_t inv_w_mantissa;  // 1/w_raw ~= mantissa * 2^-inv_w_exponent
  int inv_w_exponent;
};

// The rows whose centres 256 r + 128 lie in [y_min, y_max] (window y in 1/256 px):
// [first, end), empty when first >= end. |y| < 2^21 (the guard band), so an arithmetic
// shift is the floor division.
struct CentredRows {
  std::int32_t first, end;
};
constexpr CentredRows rows_centred_in(std::int32_t y_min, std::int32_t y_max) {
  return {(y_min - 128 + 255) >> 8, ((y_max - 128) >> 8) + 1};  // first centre >= y_min, past the last <= y_max
}

// The vertex divide's reciprocal: its table's index bits and Newton steps (the
// sweep's memory figures count this table; named here so no one has to guess it).
inline constexpr int vertex_divide_table_bits = 8;
inline constexpr int vertex_divide_newton = 2;

// (a + w) / w in Q.32 for |a| <= G*w: both are shifted by k so that w fits 28
// bits; the quotient then keeps 28 significant bits, ample for 2^20 subpixels.
struct VertexDivider {
  int k;
  fixedpoint::Reciprocal rcp;  // of w >> k
  constexpr explicit VertexDivider(std::int64_t w) : k(0), rcp{} {
    if (w < 1) w = 1;  // w >= 0 after near and far clipping; w == 0 only at the eye itself
    const int excess = fixedpoint::bit_length(static_cast<std::uint64_t>(w)) - 28;
    k = excess > 0 ? excess : 0;
    rcp = fixedpoint::reciprocal<vertex_divide_table_bits, vertex_divide_newton>(static_cast<std::uint32_t>(w >> k));
  }
  // (numerator / w) * 2^32, numerator >> k < 2^31 when |numerator| <= 7*w.
  constexpr std::int64_t ratio_q32(std::int64_t numerator) const {
    const std::int64_t n = numerator >> k;
    // ARMv6-M: a 32 x 32 product, not __muldi3, when n fits 32 bits, as it does but for a cut
    // vertex within lerp's rounding of the eye (the mantissa is below 2^31).
    const bool narrow = !fixedpoint::has_long_multiply && n == static_cast<std::int32_t>(n);
    const std::int64_t product =
        narrow ? fixedpoint::mul_s32_setup(static_cast<std::int32_t>(n), static_cast<std::int32_t>(rcp.mantissa))
               : n * static_cast<std::int64_t>(rcp.mantissa);
    const int shift = rcp.shift - 32;  // -1 only for w < 2^4 raw, where the product is tiny
    return shift >= 0 ? product >> shift : product * 2;
  }
};

constexpr std::int64_t round_q32_to_int64(std::int64_t value_q32) { return (value_q32 + (std::int64_t{1} << 31)) >> 32; }

constexpr ScreenVertex project(const Vec4Wide& c, int width, int height) {
  const VertexDivider div(c.w);
  const std::int64_t w = c.w < 1 ? 1 : c.w;
  // x_win * 256 = (x/w + 1) * width * 128; the ratio is < 2^35, times 2^19 < 2^54.
  const std::int64_t x_ratio = div.ratio_q32(c.x + w);
  const std::int64_t y_ratio = div.ratio_q32(w - c.y);  // row 0 at the top: flip y
  const std::int64_t z_ratio = div.ratio_q32(c.z + w);  // in [0, 2] after clipping
  ScreenVertex v{};
  // The guard band keeps |x| <= G w, so |x_win| < 2^21 subpixels (setup's bound), except
  // for a cut vertex within lerp's rounding of the eye (w of a few raw units), where that
  // rounding is a sizeable part of w. Clamping restores the bound and changes nothing else.
  constexpr std::int64_t limit = (std::int64_t{1} << 21) - 1;
  // mul_s64_u32: the product without __muldi3 on ARMv6-M.
  const auto x_scale = static_cast<std::uint32_t>(width) << (subpixel_bits - 1), y_scale = static_cast<std::uint32_t>(height) << (subpixel_bits - 1);
  v.x = static_cast<std::int32_t>(std::clamp(round_q32_to_int64(fixedpoint::mul_s64_u32(x_ratio, x_scale)), -limit, limit));
  v.y = static_cast<std::int32_t>(std::clamp(round_q32_to_int64(fixedpoint::mul_s64_u32(y_ratio, y_scale)), -limit, limit));
  const std::int64_t z = (z_ratio + (std::int64_t{1} << 2)) >> 3;  // /2, Q.32 -> Q.30
  v.z = static_cast<std::int32_t>(std::clamp(z, std::int64_t{0}, std::int64_t{1} << depth_frac_bits));
  v.inv_w_mantissa = div.rcp.mantissa;
  v.inv_w_exponent = div.rcp.shift + div.k;
  return v;
}

}  // namespace spanlight
