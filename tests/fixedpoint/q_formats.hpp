// The Q formats every q test runs on: each storage width, full-width and
// narrow formats, FracBits at both extremes, and the uint64 / u128 internal paths.
#pragma once

#include <cstdint>

#include "fixedpoint/q.hpp"

namespace q_formats {

using q15_16 = fixedpoint::q<15, 16>;                   // positions
using q1_30 = fixedpoint::q<1, 30>;                     // unit factors
using q0_31 = fixedpoint::q<0, 31>;                     // [-1, 1)
using q31_0 = fixedpoint::q<31, 0>;                     // plain integers
using q10_10 = fixedpoint::q<10, 10>;                   // narrower than its int32 storage
using q7_8_s16 = fixedpoint::q<7, 8, std::int16_t>;     // int16
using q0_15_s16 = fixedpoint::q<0, 15, std::int16_t>;   // int16, all fraction
using q24_8_s64 = fixedpoint::q<24, 8, std::int64_t>;   // int64 storage, uint64 intermediates
using q31_32_s64 = fixedpoint::q<31, 32, std::int64_t>; // int64, 128-bit intermediates
using q0_63_s64 = fixedpoint::q<0, 63, std::int64_t>;   // int64, all fraction
using q20_40_s64 = fixedpoint::q<20, 40, std::int64_t>; // int64, narrow, 128-bit intermediates

}  // namespace q_formats

#define Q_TEST_FORMATS                                                                                        \
  q_formats::q15_16, q_formats::q1_30, q_formats::q0_31, q_formats::q31_0, q_formats::q10_10,                  \
      q_formats::q7_8_s16, q_formats::q0_15_s16, q_formats::q24_8_s64, q_formats::q31_32_s64, q_formats::q0_63_s64, \
      q_formats::q20_40_s64
