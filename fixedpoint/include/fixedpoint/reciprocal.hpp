// Reciprocal by table lookup and Newton-Raphson, the per-span divide of the
// pipeline. 1/d is returned as a normalised mantissa and a shift:
//
//     1/d ~= mantissa * 2^-shift,   mantissa in [2^30 * (1 - e), 2^31)  (Q1.31 of 1/m)
//
// with e the relative error bound below: Newton steps round down, so for m near
// 2^32 the mantissa can end just under 2^30; it is always < 2^31 (fits int32).
//
// Steps: normalise d with CLZ so m = d << n lies in [2^31, 2^32) (the value
// m/2^31 in [1, 2)); the top TableBits bits after the leading one index a
// constexpr table of 1/midpoint (16-bit entries, in flash); each Newton step
// y <- y * (2 - m*y) squares the relative error.
//
// Relative error bounds (derived in docs/reciprocal.md; tests/fixedpoint/test_reciprocal.cpp
// checks them exhaustively over every 16-bit input and on 2^20 random
// 32-bit ones, and `spanlight_reciprocal_table` prints the measured maxima):
//   0 steps: seed error  <= 2^-(B+1) + 2^-16 (half interval / midpoint, entry rounding)
//   1 step : e1 <= e0^2 + 2^-29 (truncation in the two 32-bit products)
//   2 steps: e2 <= e1^2 + 2^-29
#pragma once

#include <array>
#include <cstdint>

#include "fixedpoint/bits.hpp"

namespace fixedpoint {

struct Reciprocal {
  std::uint32_t mantissa;  // in [2^30 * (1 - e), 2^31), e = the error bound above
  int shift;               // 1/d ~= mantissa / 2^shift
};

// 2^TableBits entries of round(2^16 / midpoint), midpoint = 1 + (i + 0.5) / 2^B.
// Every entry is < 2^16 because the first midpoint is above 1.
template <int TableBits>
struct ReciprocalTable {
  static_assert(TableBits >= 1 && TableBits <= 14, "table of 2..16384 entries");
  static constexpr std::size_t size = std::size_t{1} << TableBits;
  std::array<std::uint16_t, size> entry{};

  constexpr ReciprocalTable() {
    for (std::size_t i = 0; i < size; ++i) {
      // 2^16 / (1 + (i + 0.5)/2^B) = 2^(17+B) / (2^(B+1) + 2i + 1), rounded to nearest.
      const std::uint64_t num = std::uint64_t{1} << (17 + TableBits);
      const std::uint64_t den = (std::uint64_t{1} << (TableBits + 1)) + 2u * std::uint64_t{i} + 1u;
      entry[i] = static_cast<std::uint16_t>((num + den / 2) / den);
    }
  }
};

template <int TableBits>
inline constexpr ReciprocalTable<TableBits> reciprocal_table{};

// Reciprocal of a normalised mantissa m in [2^31, 2^32): returns y ~= 2^62 / m.
template <int TableBits, int NewtonSteps>
constexpr std::uint32_t reciprocal_normalised(std::uint32_t m) {
  static_assert(NewtonSteps >= 0 && NewtonSteps <= 2, "0, 1 or 2 Newton steps");
  const std::uint32_t index = (m >> (31 - TableBits)) & ((1u << TableBits) - 1u);
  const std::uint32_t entry = reciprocal_table<TableBits>.entry[index];  // < 2^16
  std::uint32_t y = entry << 15;                                          // Q1.31
  for (int step = 0; step < NewtonSteps; ++step) {
    // m*y is Q2.62 and close to 2^62; 2 - m*y is then close to 1 (Q2.62: 2^63 - m*y).
    // The first step's y is the entry << 15: m*y = (m * entry) << 15 (< 2^63) and
    // (y * two_minus) >> 31 = (entry * two_minus) >> 16, the same values from 32 x 16 products
    // (two 16-bit multiplies each on ARMv6-M, not four).
    const std::uint64_t my = step == 0 ? mul_u32_u16(m, entry) << 15 : mul_u32(m, y);
    const std::uint32_t two_minus = static_cast<std::uint32_t>(((std::uint64_t{1} << 63) - my) >> 31);  // Q1.31
    y = static_cast<std::uint32_t>(step == 0 ? mul_u32_u16(two_minus, entry) >> 16 : mul_u32(y, two_minus) >> 31);
  }
  return y;
}

// 1/d for d > 0.
template <int TableBits, int NewtonSteps>
constexpr Reciprocal reciprocal(std::uint32_t d) {
  const int n = clz32(d);
  const std::uint32_t m = d << n;  // d = m * 2^-n, so 1/d = (2^62/m) * 2^-(62-n)
  return {reciprocal_normalised<TableBits, NewtonSteps>(m), 62 - n};
}

// 1/d for 64-bit d > 0: the top 32 significant bits are used (relative error
// of the truncation < 2^-31, below every table's own error; with e the bound
// above, the error against the exact 1/d is <= (e + 2^-31) / (1 - 2^-31)).
template <int TableBits, int NewtonSteps>
constexpr Reciprocal reciprocal(std::uint64_t d) {
  const int n = clz64(d);
  const std::uint32_t m = static_cast<std::uint32_t>((d << n) >> 32);  // d ~= m * 2^(32-n)
  return {reciprocal_normalised<TableBits, NewtonSteps>(m), 94 - n};
}

}  // namespace fixedpoint
