// Compile-time proofs: the q policies and the 128-bit helpers hold in constant
// expressions, so a failure here is a build error, not a test failure.
#include <catch2/catch.hpp>

#include <cstdint>
#include <limits>

#include "q_formats.hpp"

namespace {

using namespace q_formats;
using fixedpoint::detail::u128;

template <typename Q>
constexpr bool half_is_top_fraction_bit() {
  return Q::from_double(0.5).raw() == (typename Q::storage{1} << (Q::frac_bits - 1)) &&
         Q::from_double(-0.5).raw() == -(typename Q::storage{1} << (Q::frac_bits - 1));
}
static_assert(half_is_top_fraction_bit<q15_16>() && half_is_top_fraction_bit<q1_30>() &&
              half_is_top_fraction_bit<q0_31>() && half_is_top_fraction_bit<q7_8_s16>() &&
              half_is_top_fraction_bit<q0_15_s16>() && half_is_top_fraction_bit<q31_32_s64>() &&
              half_is_top_fraction_bit<q0_63_s64>() && half_is_top_fraction_bit<q20_40_s64>());

// Ranges: sign + IntBits + FracBits, narrow formats included.
static_assert(q15_16::raw_max == INT32_MAX && q15_16::raw_min == INT32_MIN);
static_assert(q10_10::raw_max == (1 << 20) - 1 && q10_10::raw_min == -(1 << 20));
static_assert(q0_63_s64::raw_min == INT64_MIN && q7_8_s16::raw_max == INT16_MAX);

// NaN -> 0, +-inf saturate.
static_assert(q31_32_s64::from_double(std::numeric_limits<double>::quiet_NaN()) == q31_32_s64{});
static_assert(q31_32_s64::from_double(-std::numeric_limits<double>::infinity()) == q31_32_s64::min());
static_assert(q0_31::from_double(1.0) == q0_31::max() && q0_31::from_double(-1.0).raw() == INT32_MIN);

// Multiply: ties away from zero, truncating variant toward zero, saturation.
static_assert((q15_16::from_raw(3) * q15_16::from_double(0.5)).raw() == 2);    // 1.5 LSB -> 2
static_assert((q15_16::from_raw(-3) * q15_16::from_double(0.5)).raw() == -2);  // -1.5 LSB -> -2
static_assert(mul_trunc(q15_16::from_raw(-3), q15_16::from_double(0.5)).raw() == -1);
static_assert(q15_16::from_int(200) * q15_16::from_int(200) == q15_16::max());
static_assert(q15_16::from_int(-200) * q15_16::from_int(200) == q15_16::min());
static_assert(q0_31::min() * q0_31::min() == q0_31::max());  // (-1)^2 = 1 saturates
static_assert(q0_63_s64::min() * q0_63_s64::min() == q0_63_s64::max());
static_assert(q31_32_s64::from_double(-2.5) * q31_32_s64::from_double(1.5) == q31_32_s64::from_double(-3.75));

// Divide: rounded, saturating, divide by zero takes the numerator's sign.
static_assert((q15_16::from_int(1) / q15_16::from_int(3)).raw() == 21845);  // 65536/3 = 21845.33
static_assert((q15_16::from_int(2) / q15_16::from_int(3)).raw() == 43691);  // 43690.67
static_assert(div_trunc(q15_16::from_int(2), q15_16::from_int(3)).raw() == 43690);
static_assert(q15_16::from_int(-1) / q15_16{} == q15_16::min() && q15_16{} / q15_16{} == q15_16{});
static_assert(q31_32_s64::from_int(1) / q31_32_s64::lsb() == q31_32_s64::max());
static_assert((q31_32_s64::from_int(-7) / q31_32_s64::from_int(2)) == q31_32_s64::from_double(-3.5));

// q_cast both ways.
static_assert(fixedpoint::q_cast<q31_32_s64>(q15_16::min()) == q31_32_s64::from_int(-32768));
static_assert(fixedpoint::q_cast<q7_8_s16>(q15_16::from_int(1000)) == q7_8_s16::max());
static_assert(fixedpoint::q_cast<q15_16>(q0_63_s64::from_raw(INT64_MIN)) == q15_16::from_int(-1));

// 128-bit helpers at their extremes.
constexpr u128 square_max = fixedpoint::detail::mul_64x64(UINT64_MAX, UINT64_MAX);  // 2^128 - 2^65 + 1
static_assert(square_max.hi == UINT64_MAX - 1 && square_max.lo == 1);
constexpr fixedpoint::detail::quotient big_division = fixedpoint::detail::divide(u128{UINT64_MAX - 1, 1}, UINT64_MAX);
static_assert(!big_division.overflow && big_division.quot == UINT64_MAX && big_division.rem == 0);
static_assert(fixedpoint::detail::divide(u128{5, 0}, 5).overflow);

}  // namespace

TEST_CASE("q compile-time proofs are compiled in", "[q]") { SUCCEED("the static_asserts above passed"); }
