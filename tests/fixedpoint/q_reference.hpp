// Exact reference results for fixedpoint::q, computed independently with
// __int128 (host only): the correctly rounded value under the documented policy
// (ties away from zero, or toward zero for *_trunc), then saturated.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "fixedpoint/q.hpp"

namespace q_reference {

using i128 = __int128;

// n / d rounded to nearest (ties away from zero) or toward zero; d != 0.
inline i128 divide(i128 n, i128 d, bool nearest) {
  const bool negative = (n < 0) != (d < 0);
  const i128 an = n < 0 ? -n : n;
  const i128 ad = d < 0 ? -d : d;
  i128 mag = an / ad;
  if (nearest && 2 * (an % ad) >= ad) ++mag;
  return negative ? -mag : mag;
}

template <typename Q>
typename Q::storage saturate(i128 v) {
  if (v > Q::raw_max) return Q::raw_max;
  if (v < Q::raw_min) return Q::raw_min;
  return static_cast<typename Q::storage>(v);
}

inline i128 pow2(int n) { return static_cast<i128>(1) << n; }

template <typename Q>
typename Q::storage mul(typename Q::storage a, typename Q::storage b, bool nearest) {
  return saturate<Q>(divide(static_cast<i128>(a) * b, pow2(Q::frac_bits), nearest));
}

template <typename Q>
typename Q::storage div(typename Q::storage a, typename Q::storage b, bool nearest) {
  if (b == 0) return a > 0 ? Q::raw_max : (a < 0 ? Q::raw_min : 0);
  return saturate<Q>(divide(static_cast<i128>(a) * pow2(Q::frac_bits), b, nearest));
}

template <typename To, typename From>
typename To::storage cast(typename From::storage a, bool nearest) {
  const int shift = To::frac_bits - From::frac_bits;
  if (shift >= 0) return saturate<To>(static_cast<i128>(a) * pow2(shift));
  return saturate<To>(divide(a, pow2(-shift), nearest));
}

// x * 2^F is exact in long double (64-bit mantissa >= double's 53, F <= 63).
template <typename Q>
typename Q::storage from_double(double x, bool nearest) {
  if (std::isnan(x)) return 0;
  const long double scaled = std::ldexp(static_cast<long double>(x), Q::frac_bits);
  const long double limit = std::ldexp(1.0L, Q::magnitude_bits);
  if (scaled >= limit) return Q::raw_max;
  if (scaled <= -limit) return Q::raw_min;
  const long double r = nearest ? std::round(scaled) : std::trunc(scaled);  // round: ties away from zero
  return saturate<Q>(static_cast<i128>(r));
}

// Wrapping add modulo 2^(1 + magnitude_bits), sign-extended.
template <typename Q>
typename Q::storage wrap(i128 v) {
  const i128 modulus = pow2(Q::magnitude_bits + 1);
  i128 r = v % modulus;
  if (r < 0) r += modulus;
  if (r > Q::raw_max) r -= modulus;
  return static_cast<typename Q::storage>(r);
}

// Raw values that exercise the edges: zero, +-1 LSB, +-0.5, 0xFFFF carries,
// +-1.0, the limits and their neighbours, and values near sqrt(limit) where
// products start to saturate.
template <typename Q>
std::vector<typename Q::storage> corner_raws() {
  const i128 max = Q::raw_max;
  const i128 min = Q::raw_min;
  std::vector<i128> candidates = {0, 1, -1, 2, -2, 3, -3, 0x7FFF, 0x8000, 0xFFFF, 0x10000, 0x1FFFF, 0x17FFF,
                                  -0xFFFF, -0x10000, -0x8000, max, max - 1, min, min + 1, max / 2, min / 2,
                                  max / 3, min / 3};
  if (Q::frac_bits >= 1) {
    const i128 half = pow2(Q::frac_bits - 1);
    for (const i128 v : {half, -half, half - 1, half + 1, -half - 1, -half + 1}) candidates.push_back(v);
  }
  const i128 one = pow2(Q::frac_bits);
  for (const i128 v : {one, -one, one - 1, one + 1, -one + 1, -one - 1, 3 * one / 2, -3 * one / 2})
    candidates.push_back(v);
  const int root_bits = (Q::magnitude_bits + Q::frac_bits) / 2;  // a * b ~ the limit
  for (const i128 v : {pow2(root_bits), pow2(root_bits) - 1, -pow2(root_bits) + 1, pow2(root_bits) + 1})
    candidates.push_back(v);
  std::vector<typename Q::storage> out;
  for (const i128 v : candidates) {
    if (v >= min && v <= max) out.push_back(static_cast<typename Q::storage>(v));
  }
  return out;
}

// A random raw with a uniformly random bit length, so small, medium and huge
// magnitudes are equally likely (uniform raws would nearly always saturate products).
template <typename Q>
typename Q::storage random_raw(std::mt19937_64& rng) {
  const int length = static_cast<int>(rng() % static_cast<std::uint64_t>(Q::magnitude_bits + 1));
  const std::uint64_t mag = length == 0 ? 0 : rng() >> (64 - length);
  const i128 v = (rng() & 1u) ? -static_cast<i128>(mag) - static_cast<i128>(rng() & 1u) : static_cast<i128>(mag);
  return saturate<Q>(v);
}

}  // namespace q_reference
