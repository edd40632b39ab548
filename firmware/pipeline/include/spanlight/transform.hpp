// Stage 1, transform: object space to clip space and to each projector's
// (s, t, r, q). Matrices are block floating point (int32 mantissas, one
// shared exponent) prepared on the host; positions are Q15.16; results are
// int64 with 32 fraction bits, enough to keep 1/256 px after the divide even
// at w = 0.01 (a near plane of a centimetre).
#pragma once

#include <cstdint>

namespace spanlight {

struct Mat4Block {
  std::int32_t m[16];  // column-major like GLM; |m| < 2^29
  std::int8_t frac_bits;  // value = m * 2^-frac_bits, 0..60
};

struct Vec4Wide {
  std::int64_t x, y, z, w;  // Q31.32
};

inline constexpr int wide_frac_bits = 32;
inline constexpr int position_frac_bits = 16;

// Row r of M times (x, y, z, 1). Products are < 2^29 * 2^30 = 2^59, the sum of
// four < 2^61, so int64 never overflows; one rounded shift brings the result
// to 32 fraction bits (frac_bits + 16 - 32 may be negative: then shift left).
constexpr std::int64_t transform_row(const Mat4Block& mat, int r, const std::int32_t* p) {
  const std::int64_t acc = std::int64_t{mat.m[r]} * p[0] + std::int64_t{mat.m[4 + r]} * p[1] +
                           std::int64_t{mat.m[8 + r]} * p[2] +
                           (std::int64_t{mat.m[12 + r]} << position_frac_bits);
  const int shift = mat.frac_bits + position_frac_bits - wide_frac_bits;
  if (shift > 0) return (acc + (std::int64_t{1} << (shift - 1))) >> shift;
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(acc) << -shift);
}

constexpr Vec4Wide transform(const Mat4Block& mat, const std::int32_t* position) {
  return {transform_row(mat, 0, position), transform_row(mat, 1, position), transform_row(mat, 2, position),
          transform_row(mat, 3, position)};
}

}  // namespace spanlight
