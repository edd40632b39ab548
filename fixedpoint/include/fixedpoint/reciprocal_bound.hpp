// The proven relative error bound of fixedpoint::reciprocal for 32-bit inputs,
// |approx * d - 1| (derivation in docs/reciprocal.md; tests/fixedpoint checks
// the measured maxima against it, and the CLI warns about knobs beyond it):
//   e0      = 2^-(B+1) + 2^-16   table seed: half an interval over the midpoint, entry rounding
//   e_(k+1) = e_k^2 + 2^-29      one Newton step: squares the error, plus < 3 * 2^-31 of truncation
// Host-side arithmetic (long double); the firmware never evaluates it.
#pragma once

#include <cstdint>

namespace fixedpoint {

constexpr long double reciprocal_error_bound(int table_bits, int newton_steps) {
  long double e = 1.0L / static_cast<long double>(std::uint64_t{1} << (table_bits + 1)) + 1.0L / 65536.0L;
  for (int step = 0; step < newton_steps; ++step) e = e * e + 1.0L / static_cast<long double>(std::uint64_t{1} << 29);
  return e;
}

}  // namespace fixedpoint
