// Measures the relative error of fixedpoint::reciprocal against the exact 1/d,
// and derives the proven bound it must stay under. Shared by test_reciprocal.cpp
// and the spanlight_reciprocal_table tool, so both report the same numbers.
#pragma once

#include <cstdint>
#include <random>

#include "fixedpoint/reciprocal.hpp"
#include "fixedpoint/reciprocal_bound.hpp"

namespace reciprocal_error {

// Proven bound for 32-bit inputs: fixedpoint/reciprocal_bound.hpp.
inline long double bound_u32(int table_bits, int newton_steps) {
  return fixedpoint::reciprocal_error_bound(table_bits, newton_steps);
}

// The 64-bit overload first truncates d to its top 32 significant bits (relative
// error eta in [0, 2^-31)), so against the exact 1/d: |e| <= (e_k + eta) / (1 - eta).
inline long double bound_u64(int table_bits, int newton_steps) {
  const long double eta = 1.0L / static_cast<long double>(std::uint64_t{1} << 31);
  return (bound_u32(table_bits, newton_steps) + eta) / (1.0L - eta);
}

struct Stats {
  long double max_error = 0;  // max |mantissa * 2^-shift * d - 1|
  std::uint64_t worst_d = 0;
  std::uint32_t min_mantissa = UINT32_MAX;
  std::uint32_t max_mantissa = 0;
  std::uint64_t count = 0;

  void merge(const Stats& other) {
    if (other.max_error > max_error) {
      max_error = other.max_error;
      worst_d = other.worst_d;
    }
    if (other.min_mantissa < min_mantissa) min_mantissa = other.min_mantissa;
    if (other.max_mantissa > max_mantissa) max_mantissa = other.max_mantissa;
    count += other.count;
  }
};

// |r * d - 1| with r = mantissa / 2^shift: mantissa * d < 2^95 and 2^shift <= 2^94,
// so the numerator is an exact __int128 and the only rounding is the final division.
inline long double relative_error(fixedpoint::Reciprocal r, std::uint64_t d) {
  const __int128 scaled_one = static_cast<__int128>(1) << r.shift;
  __int128 diff = static_cast<__int128>(r.mantissa) * d - scaled_one;
  if (diff < 0) diff = -diff;
  return static_cast<long double>(diff) / static_cast<long double>(scaled_one);
}

inline void record(Stats& s, fixedpoint::Reciprocal r, std::uint64_t d) {
  const long double e = relative_error(r, d);
  if (e > s.max_error) {
    s.max_error = e;
    s.worst_d = d;
  }
  if (r.mantissa < s.min_mantissa) s.min_mantissa = r.mantissa;
  if (r.mantissa > s.max_mantissa) s.max_mantissa = r.mantissa;
  ++s.count;
}

// Every d in [1, 65535], through the 32-bit overload.
template <int B, int Steps>
Stats exhaustive_u16() {
  Stats s;
  for (std::uint32_t d = 1; d <= 0xFFFFu; ++d) record(s, fixedpoint::reciprocal<B, Steps>(d), d);
  return s;
}

// count uniformly random d over the full 32-bit range (0 is redrawn).
template <int B, int Steps>
Stats random_u32(std::uint32_t seed, std::uint32_t count) {
  std::mt19937 rng(seed);
  Stats s;
  for (std::uint32_t i = 0; i < count; ++i) {
    std::uint32_t d = 0;
    while (d == 0) d = static_cast<std::uint32_t>(rng());
    record(s, fixedpoint::reciprocal<B, Steps>(d), d);
  }
  return s;
}

// count random 64-bit d with a uniformly random bit length in [1, 64], so every
// magnitude is covered, including the ones where truncation to 32 bits matters.
template <int B, int Steps>
Stats random_u64(std::uint32_t seed, std::uint32_t count) {
  std::mt19937 rng(seed);
  Stats s;
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint64_t bits = (std::uint64_t{rng()} << 32) | rng();
    const int length = static_cast<int>(rng() % 64u) + 1;
    std::uint64_t d = bits >> (64 - length);
    d |= std::uint64_t{1} << (length - 1);  // exactly `length` bits, never 0
    record(s, fixedpoint::reciprocal<B, Steps>(d), d);
  }
  return s;
}

}  // namespace reciprocal_error
