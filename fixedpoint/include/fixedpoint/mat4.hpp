// Mat4: a 4x4 matrix being built at run time, and the status of building it.
// Builders (look_at, perspective, bias) return one, a product keeps the first
// failure, and pipeline_matrix() turns the result into the pipeline's Mat4Block
// (vec.hpp), so a chain reads like GLM's and is checked once at the end:
//     BlockResult clip = pipeline_matrix(perspective(...) * (look_at(...) * mat4(model)));
//
// Storage: int32 mantissas below 2^29 with one exponent per COLUMN,
//     value(col, row) = m[col * 4 + row] * 2^-frac_bits[col],  frac_bits in [0, 60],
// because the columns of a pose are of unrelated sizes (rotation against
// translation; P00 = cot(fovy/2)/aspect, P22 ~ -1 and P32 ~ -2 near), while the
// pipeline's single exponent is applied only once, at the end. Each column's
// frac_bits is the largest that keeps its rounded |mantissas| < 2^29 (the rule of
// mat4_block_from_doubles), so its largest mantissa is >= 2^28 and rounding an
// entry costs at most half a unit, 2^-(frac_bits + 1) <= 2^-29 times the column's
// largest entry (or 2^-61 when the column's frac_bits is capped at 60).
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/pose_status.hpp"
#include "fixedpoint/q.hpp"
#include "fixedpoint/vec.hpp"

namespace fixedpoint {

struct Mat4 {
  std::int32_t m[16];  // column-major: m[col * 4 + row], |m| < 2^29
  int frac_bits[4];    // per column, in [0, 60]
  PoseStatus status;
};

// value = mantissa * 2^-frac, |mantissa| < 2^63: an exact intermediate on its way into a Mat4.
struct Scaled {
  std::int64_t mantissa;
  int frac;
};

// The pipeline's matrix and whether it could be made.
struct BlockResult {
  Mat4Block block;
  PoseStatus status;
};

namespace detail {

// round(|m| * 2^shift) for any shift: exact left shifts (the caller keeps a non-zero
// result below 2^29, so shift < 29), right shifts rounded half up; beyond 63 bits the value is < 1/2.
constexpr std::uint64_t scaled_magnitude(std::uint64_t mag, int shift) {
  if (mag == 0) return 0;
  if (shift >= 0) return mag << shift;
  if (shift < -63) return 0;
  return (mag + (std::uint64_t{1} << (-shift - 1))) >> -shift;
}

// Quantises count exact values to one exponent: the largest frac_bits in [0, 60] with every
// rounded |mantissa| < 2^29, rounding to nearest (ties away from zero). False when even
// frac_bits 0 does not fit (some |value| rounds to >= 2^29).
constexpr bool quantise(const Scaled* entries, int count, std::int32_t* out, int& frac_bits) {
  // top: every |value| < 2^top, and the largest one is >= 2^(top - 1).
  constexpr int none = -1000;
  int top = none;
  for (int i = 0; i < count; ++i) {
    if (entries[i].mantissa == 0) continue;
    const int t = bit_length(magnitude(entries[i].mantissa)) - entries[i].frac;
    if (t > top) top = t;
  }
  // 29 - top keeps every |value| * 2^frac_bits < 2^29; one less if the largest rounds up to
  // 2^29. One more would put the largest at >= 2^29.
  frac_bits = top == none || 29 - top > mat4_block_max_frac_bits ? mat4_block_max_frac_bits : 29 - top;
  for (int attempt = 0; attempt < 2 && frac_bits >= 0; ++attempt, --frac_bits) {
    bool fits = true;
    for (int i = 0; i < count; ++i) {
      const std::uint64_t m = scaled_magnitude(magnitude(entries[i].mantissa), frac_bits - entries[i].frac);
      if (m >= static_cast<std::uint64_t>(mat4_block_entry_limit)) fits = false;
      out[i] = static_cast<std::int32_t>(entries[i].mantissa < 0 ? -static_cast<std::int64_t>(m) : static_cast<std::int64_t>(m));
    }
    if (fits) return true;
  }
  return false;
}

// x / 2^s rounded to nearest (ties away from zero) for any s >= 0 and |x| < 2^62.
constexpr std::int64_t rescale_right(std::int64_t x, int s) {
  if (s == 0) return x;
  if (s > 62) return 0;  // |x| / 2^63 < 1/2
  return shift_right_rounded(x, s);
}

}  // namespace detail

// Quantise 16 exact values (column-major) into a Mat4, each column to its own exponent;
// entry_out_of_range when some |value| rounds to >= 2^29 even at frac_bits 0.
constexpr Mat4 mat4_from_scaled(const Scaled (&entries)[16]) {
  Mat4 out{};
  for (int col = 0; col < 4; ++col) {
    if (!detail::quantise(&entries[col * 4], 4, &out.m[col * 4], out.frac_bits[col])) {
      return {{}, {}, PoseStatus::entry_out_of_range};
    }
  }
  out.status = PoseStatus::ok;
  return out;
}

// Quantise 16 exact values into one block, as mat4_block_from_doubles does for doubles.
constexpr BlockResult block_from_scaled(const Scaled (&entries)[16]) {
  BlockResult out{};
  if (!detail::quantise(entries, 16, out.block.m, out.block.frac_bits)) return {{}, PoseStatus::entry_out_of_range};
  out.status = PoseStatus::ok;
  return out;
}

// A given block (a baked model matrix), checked against the format's bounds. Exact.
constexpr Mat4 mat4(const Mat4Block& block) {
  if (block.frac_bits < 0 || block.frac_bits > mat4_block_max_frac_bits) return {{}, {}, PoseStatus::entry_out_of_range};
  Mat4 out{};
  for (int i = 0; i < 16; ++i) {
    if (block.m[i] <= -mat4_block_entry_limit || block.m[i] >= mat4_block_entry_limit) return {{}, {}, PoseStatus::entry_out_of_range};
    out.m[i] = block.m[i];
  }
  for (int& f : out.frac_bits) f = block.frac_bits;
  out.status = PoseStatus::ok;
  return out;
}

// a * b, or the first operand's failure. Column j of the product sums the terms
// a_ik b_kj, each exact in int64 (< 2^58) at frac_bits a_k + b_j. Terms of finer columns
// of a are first rounded to the coarsest of them (a_k with b_kj != 0): at most 3 such
// roundings, each half a unit there, so <= 1.5 * 2^-(min_k frac_a[k] + frac_b[j]) per
// entry (~2^-56 of |a| |b|); then the column's own rounding.
constexpr Mat4 operator*(const Mat4& a, const Mat4& b) {
  if (a.status != PoseStatus::ok) return a;
  if (b.status != PoseStatus::ok) return b;
  Scaled product[16] = {};
  for (int col = 0; col < 4; ++col) {
    const std::int32_t* bc = &b.m[col * 4];
    int coarsest = mat4_block_max_frac_bits;
    for (int k = 0; k < 4; ++k) {
      if (bc[k] != 0 && a.frac_bits[k] < coarsest) coarsest = a.frac_bits[k];
    }
    for (int row = 0; row < 4; ++row) {
      std::int64_t sum = 0;
      for (int k = 0; k < 4; ++k) {
        const std::int32_t ak = a.m[k * 4 + row];
        if (ak == 0 || bc[k] == 0) continue;  // P and B are mostly zeros
        sum += detail::rescale_right(mul_s32(ak, bc[k]), a.frac_bits[k] - coarsest);
      }
      product[col * 4 + row] = {sum, coarsest + b.frac_bits[col]};  // |sum| < 4 * 2^58
    }
  }
  return mat4_from_scaled(product);
}

// B = translate(1/2) * scale(1/2): clip coordinates in [-w, w] to texture coordinates
// and depth in [0, w]. Exact.
constexpr Mat4 bias() {
  const Scaled half{1, 1}, one{1, 0}, zero{0, 0};
  const Scaled entries[16] = {half, zero, zero, zero, zero, half, zero, zero, zero, zero, half, zero, half, half, half, one};
  return mat4_from_scaled(entries);
}

// The matrix as the pipeline takes it: one exponent for all entries (rounding each to
// nearest, half a unit of the block's last place), or the chain's failure, or
// beyond_pipeline_range when an entry may be >= 2^13 (frac_bits below 16, vec.hpp).
constexpr BlockResult pipeline_matrix(const Mat4& m) {
  if (m.status != PoseStatus::ok) return {{}, m.status};
  Scaled entries[16] = {};
  for (int i = 0; i < 16; ++i) entries[i] = {m.m[i], m.frac_bits[i / 4]};
  const BlockResult out = block_from_scaled(entries);
  if (out.status == PoseStatus::ok && out.block.frac_bits < mat4_block_pipeline_min_frac_bits) {
    return {out.block, PoseStatus::beyond_pipeline_range};
  }
  return out;
}

}  // namespace fixedpoint
