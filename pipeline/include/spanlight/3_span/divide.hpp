// The divide of the perspective step: a table reciprocal plus Newton steps
// (fixedpoint/reciprocal.hpp). Firmware fixes the table and the steps at
// bake time (Features::table_bits, newton), so the call is direct; the host
// takes them from the knobs and picks the same function by a switch. Either
// way the same fixedpoint::reciprocal<B, S> does the work: the bytes agree.
#pragma once

#include <cstdint>

#include "fixedpoint/reciprocal.hpp"
#include "spanlight/features.hpp"

namespace spanlight {

template <int TableBits, int NewtonSteps>
struct FixedDivide {
  constexpr fixedpoint::Reciprocal of(std::uint32_t d) const { return fixedpoint::reciprocal<TableBits, NewtonSteps>(d); }
  // 2^62 / m for m already in [2^31, 2^32): of(m) without the CLZ (a libgcc call on ARMv6-M).
  constexpr std::uint32_t of_normalised(std::uint32_t m) const {
    return fixedpoint::reciprocal_normalised<TableBits, NewtonSteps>(m);
  }
};

// The knobs' table and steps, chosen at run time (host builds: Features::table_bits == 0).
struct KnobDivide {
  std::uint8_t table_bits, newton;

  constexpr fixedpoint::Reciprocal of(std::uint32_t d) const {
    const int n = fixedpoint::clz32(d);
    return {of_normalised(d << n), 62 - n};
  }
  constexpr std::uint32_t of_normalised(std::uint32_t m) const {
    switch (table_bits * 4 + newton) {
      case 6 * 4 + 0: return fixedpoint::reciprocal_normalised<6, 0>(m);
      case 6 * 4 + 1: return fixedpoint::reciprocal_normalised<6, 1>(m);
      case 6 * 4 + 2: return fixedpoint::reciprocal_normalised<6, 2>(m);
      case 8 * 4 + 0: return fixedpoint::reciprocal_normalised<8, 0>(m);
      case 8 * 4 + 1: return fixedpoint::reciprocal_normalised<8, 1>(m);
      case 8 * 4 + 2: return fixedpoint::reciprocal_normalised<8, 2>(m);
      case 10 * 4 + 0: return fixedpoint::reciprocal_normalised<10, 0>(m);
      case 10 * 4 + 1: return fixedpoint::reciprocal_normalised<10, 1>(m);
      case 10 * 4 + 2: return fixedpoint::reciprocal_normalised<10, 2>(m);
      case 12 * 4 + 0: return fixedpoint::reciprocal_normalised<12, 0>(m);
      case 12 * 4 + 1: return fixedpoint::reciprocal_normalised<12, 1>(m);
      default: return fixedpoint::reciprocal_normalised<12, 2>(m);
    }
  }
};

// The divide a build with features F uses: fixed when F says, else the knobs'.
template <Features F>
constexpr auto divide_for(const Knobs& knobs) {
  if constexpr (F.table_bits != 0) return FixedDivide<F.table_bits, F.newton>{};
  else return KnobDivide{knobs.table_bits, knobs.newton};
}

}  // namespace spanlight
