// Q-format fixed-point numbers: value = raw * 2^-FracBits, where raw is a signed
// integer with a sign bit, IntBits integer bits and FracBits fraction bits.
//
// Policies, the same for every operation unless its name says otherwise:
//   rounding   to nearest, ties away from zero (2.5 -> 3, -2.5 -> -3) on multiply,
//              divide, q_cast and from_double. The *_trunc variants round toward
//              zero instead (C's integer-division rule).
//   overflow   saturate to [min(), max()]. Wrapping happens only in wrapping_add,
//              wrapping_sub and wrapping_neg, modulo 2^(1 + IntBits + FracBits).
//   from_double / from_float: NaN -> 0, +-inf and out-of-range values -> max()/min()
//              (D3D11's float -> fixed rule; the rounding is the one above).
//   divide by zero: x/0 = max() if x > 0, min() if x < 0, and 0/0 = 0 (a NaN, so 0
//              as in from_double).
//
// The raw range is [-2^(IntBits+FracBits), 2^(IntBits+FracBits) - 1]; a format
// narrower than Storage keeps its unused top bits as copies of the sign.
//
// Freestanding: no heap, no exceptions, no RTTI, no <cmath>; everything is
// constexpr. Products of int64 formats use a 128-bit magnitude built from 32-bit
// halves, because arm-none-eabi (a 32-bit target) has no __int128.
#pragma once

#include <compare>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace fixedpoint {

enum class rounding { nearest, toward_zero };  // nearest: ties away from zero

namespace detail {

// Operations work on sign + magnitude: rounding a magnitude half-up is exactly
// "ties away from zero" for either sign, and truncating it is "toward zero".
constexpr std::uint64_t magnitude(std::int64_t x) {
  // Unsigned negation, so INT64_MIN gives 2^63 instead of overflowing.
  return x < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(x) : static_cast<std::uint64_t>(x);
}

struct u128 {
  std::uint64_t hi;
  std::uint64_t lo;
};

// Magnitude type for intermediates up to 2^MaxLog2 plus a rounding half (<= 2^62):
// uint64 while that stays below 2^64 (every int16/int32 multiply and divide), else u128.
template <int MaxLog2>
using wide_for = std::conditional_t<(MaxLog2 <= 62), std::uint64_t, u128>;

template <typename W>
constexpr W widen(std::uint64_t x) {
  if constexpr (std::is_same_v<W, std::uint64_t>) {
    return x;
  } else {
    return u128{0, x};
  }
}

// The exact 128-bit a * b: schoolbook on 32-bit halves. Each partial product is
// < 2^64 and mid < 3 * 2^32, so no sum below can overflow.
constexpr u128 mul_64x64(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t a_lo = a & 0xFFFFFFFFu, a_hi = a >> 32;
  const std::uint64_t b_lo = b & 0xFFFFFFFFu, b_hi = b >> 32;
  const std::uint64_t ll = a_lo * b_lo, lh = a_lo * b_hi, hl = a_hi * b_lo, hh = a_hi * b_hi;
  const std::uint64_t mid = (ll >> 32) + (lh & 0xFFFFFFFFu) + (hl & 0xFFFFFFFFu);
  return u128{hh + (lh >> 32) + (hl >> 32) + (mid >> 32), (mid << 32) | (ll & 0xFFFFFFFFu)};
}

// Shifts take 0 <= s <= 63 (every caller shifts by at most a FracBits).
constexpr std::uint64_t shl(std::uint64_t x, int s) { return x << s; }
constexpr u128 shl(u128 x, int s) {
  return s == 0 ? x : u128{(x.hi << s) | (x.lo >> (64 - s)), x.lo << s};
}
constexpr std::uint64_t shr(std::uint64_t x, int s) { return x >> s; }
constexpr u128 shr(u128 x, int s) {
  return s == 0 ? x : u128{x.hi >> s, (x.lo >> s) | (x.hi << (64 - s))};
}

constexpr std::uint64_t add(std::uint64_t x, std::uint64_t y) { return x + y; }
constexpr u128 add(u128 x, std::uint64_t y) {
  const std::uint64_t lo = x.lo + y;
  return u128{x.hi + (lo < y ? 1u : 0u), lo};
}

constexpr bool exceeds(std::uint64_t x, std::uint64_t limit) { return x > limit; }
constexpr bool exceeds(u128 x, std::uint64_t limit) { return x.hi != 0 || x.lo > limit; }

constexpr std::uint64_t low64(std::uint64_t x) { return x; }
constexpr std::uint64_t low64(u128 x) { return x.lo; }

// x / 2^s with the magnitude rounded half-up (nearest) or truncated (toward zero).
template <typename W>
constexpr W shr_rounded(W x, int s, rounding mode) {
  if (s == 0) return x;
  if (mode == rounding::nearest) x = add(x, std::uint64_t{1} << (s - 1));
  return shr(x, s);
}

struct quotient {
  std::uint64_t quot;
  std::uint64_t rem;
  bool overflow;  // quotient >= 2^64: larger than any format, the caller saturates
};

constexpr quotient divide(std::uint64_t n, std::uint64_t d) { return {n / d, n % d, false}; }
constexpr quotient divide(u128 n, std::uint64_t d) {
  if (n.hi >= d) return {0, 0, true};
  // Restoring division, one quotient bit per step. Invariant rem < d; the shifted
  // rem < 2d may carry out of 64 bits, and then it is certainly >= d and the
  // modular subtraction gives the true remainder (< d).
  std::uint64_t rem = n.hi, quot = 0;
  for (int bit = 63; bit >= 0; --bit) {
    const bool carry = (rem >> 63) != 0;
    rem = (rem << 1) | ((n.lo >> bit) & 1u);
    quot <<= 1;
    if (carry || rem >= d) {
      rem -= d;
      quot |= 1u;
    }
  }
  return {quot, rem, false};
}

// Signed raw from sign + magnitude, clamped to [-(max_mag + 1), max_mag].
template <typename W>
constexpr std::int64_t saturate_signed(bool negative, W mag, std::uint64_t max_mag) {
  if (!negative) return static_cast<std::int64_t>(exceeds(mag, max_mag) ? max_mag : low64(mag));
  if (exceeds(mag, max_mag + 1)) return -static_cast<std::int64_t>(max_mag) - 1;
  // Modular negation then conversion (defined in C++20): a magnitude of 2^63 gives INT64_MIN.
  return static_cast<std::int64_t>(std::uint64_t{0} - low64(mag));
}

// 2^n as a double, exact for -1074 <= n <= 1023; constexpr without <cmath>.
constexpr double pow2(int n) {
  double p = 1.0;
  for (; n > 0; --n) p *= 2.0;
  for (; n < 0; ++n) p *= 0.5;
  return p;
}

}  // namespace detail

template <int IntBits, int FracBits, typename Storage = std::int32_t>
class q {
  static_assert(std::is_same_v<Storage, std::int16_t> || std::is_same_v<Storage, std::int32_t> ||
                    std::is_same_v<Storage, std::int64_t>,
                "Storage is int16_t, int32_t or int64_t");
  static_assert(IntBits >= 0 && FracBits >= 0, "bit counts are non-negative");
  static_assert(1 + IntBits + FracBits <= 8 * static_cast<int>(sizeof(Storage)),
                "sign + IntBits + FracBits must fit in Storage");

 public:
  using storage = Storage;
  static constexpr int int_bits = IntBits;
  static constexpr int frac_bits = FracBits;
  static constexpr int magnitude_bits = IntBits + FracBits;  // <= 63
  static constexpr std::uint64_t max_magnitude = (std::uint64_t{1} << magnitude_bits) - 1;
  static constexpr double lsb_value = detail::pow2(-FracBits);  // exact powers of two, folded at compile time
  static constexpr double raw_scale = detail::pow2(FracBits);
  static constexpr double raw_limit = detail::pow2(magnitude_bits);  // raw_max + 1 = -raw_min
  static constexpr Storage raw_max = static_cast<Storage>(max_magnitude);
  static constexpr Storage raw_min = static_cast<Storage>(-static_cast<std::int64_t>(max_magnitude) - 1);

  constexpr q() = default;  // zero

  // Exact, except that a raw outside a narrow format's range saturates.
  static constexpr q from_raw(Storage r) { return make(r > raw_max ? raw_max : (r < raw_min ? raw_min : r)); }
  constexpr Storage raw() const { return raw_; }

  static constexpr q max() { return make(raw_max); }
  static constexpr q min() { return make(raw_min); }  // the most negative value
  static constexpr q lsb() { return make(1); }        // 2^-FracBits

  static constexpr q from_int(std::int64_t n) {
    // n * 2^F fits exactly when -2^IntBits <= n < 2^IntBits.
    constexpr std::int64_t int_max = static_cast<std::int64_t>(max_magnitude >> FracBits);
    constexpr std::int64_t int_min = -int_max - 1;
    if (n > int_max) return max();
    if (n < int_min) return min();
    // Shifted as unsigned: for FracBits = 63 a signed n * 2^63 would overflow even for n = -1.
    return make(static_cast<Storage>(static_cast<std::int64_t>(static_cast<std::uint64_t>(n) << FracBits)));
  }

  static constexpr q from_double(double x) { return convert(x, rounding::nearest); }
  static constexpr q from_double_trunc(double x) { return convert(x, rounding::toward_zero); }
  static constexpr q from_float(float x) { return from_double(static_cast<double>(x)); }  // exact widening
  static constexpr q from_float_trunc(float x) { return from_double_trunc(static_cast<double>(x)); }

  // Exact when magnitude_bits <= 53; otherwise rounded once, to nearest even.
  constexpr double to_double() const { return static_cast<double>(raw_) * lsb_value; }
  // Rounded once when magnitude_bits <= 53 (the double in between is exact).
  constexpr float to_float() const { return static_cast<float>(to_double()); }

  friend constexpr bool operator==(const q&, const q&) = default;
  friend constexpr auto operator<=>(const q&, const q&) = default;

  constexpr q operator+() const { return *this; }
  constexpr q operator-() const { return raw_ == raw_min ? max() : make(static_cast<Storage>(-raw_)); }

  friend constexpr q operator+(q a, q b) { return add_saturating(a.raw_, b.raw_, false); }
  friend constexpr q operator-(q a, q b) { return add_saturating(a.raw_, b.raw_, true); }
  friend constexpr q operator*(q a, q b) { return multiply(a, b, rounding::nearest); }
  friend constexpr q operator/(q a, q b) { return divide(a, b, rounding::nearest); }
  friend constexpr q mul_trunc(q a, q b) { return multiply(a, b, rounding::toward_zero); }
  friend constexpr q div_trunc(q a, q b) { return divide(a, b, rounding::toward_zero); }

  constexpr q& operator+=(q b) { return *this = *this + b; }
  constexpr q& operator-=(q b) { return *this = *this - b; }
  constexpr q& operator*=(q b) { return *this = *this * b; }
  constexpr q& operator/=(q b) { return *this = *this / b; }

  friend constexpr q wrapping_add(q a, q b) {
    return make(wrap(static_cast<std::uint64_t>(a.raw_) + static_cast<std::uint64_t>(b.raw_)));
  }
  friend constexpr q wrapping_sub(q a, q b) {
    return make(wrap(static_cast<std::uint64_t>(a.raw_) - static_cast<std::uint64_t>(b.raw_)));
  }
  friend constexpr q wrapping_neg(q a) { return make(wrap(std::uint64_t{0} - static_cast<std::uint64_t>(a.raw_))); }

 private:
  Storage raw_{0};

  static constexpr q make(Storage r) {
    q x;
    x.raw_ = r;
    return x;
  }

  // Keeps the low 1 + magnitude_bits bits and sign-extends from the format's sign bit.
  static constexpr Storage wrap(std::uint64_t bits) {
    constexpr int unused = 63 - magnitude_bits;
    return static_cast<Storage>(static_cast<std::int64_t>(bits << unused) >> unused);
  }

  static constexpr q add_saturating(std::int64_t a, std::int64_t b, bool subtract) {
    if constexpr (sizeof(Storage) < 8) {
      // |a|, |b| <= 2^31, so the exact sum fits int64; clamp it.
      const std::int64_t sum = subtract ? a - b : a + b;
      return make(static_cast<Storage>(sum > raw_max ? raw_max : (sum < raw_min ? raw_min : sum)));
    } else {
      // Modular sum; it overflowed int64 exactly when the operands (b negated for a
      // subtraction) share a sign that the result lacks.
      const std::uint64_t ub = static_cast<std::uint64_t>(b);
      const auto sum = static_cast<std::int64_t>(static_cast<std::uint64_t>(a) + (subtract ? std::uint64_t{0} - ub : ub));
      const bool b_non_negative = subtract ? b < 0 : b >= 0;  // sign of the addend
      if (a >= 0 && b_non_negative && sum < 0) return max();
      if (a < 0 && !b_non_negative && sum >= 0) return min();
      return make(static_cast<Storage>(sum > raw_max ? raw_max : (sum < raw_min ? raw_min : sum)));
    }
  }

  static constexpr q multiply(q a, q b, rounding mode) {
    // |a|, |b| <= 2^magnitude_bits: the exact product is <= 2^(2 * magnitude_bits).
    if constexpr (2 * magnitude_bits <= 62) {
      // Every int16/int32 format: the signed int64 product, and it plus or minus a
      // rounding half (< 2^62 in magnitude), cannot overflow. The short Cortex-M path.
      constexpr std::int64_t half_lsb = (std::int64_t{1} << FracBits) >> 1;  // 0 when FracBits = 0
      const std::int64_t half = mode == rounding::nearest ? half_lsb : 0;
      const std::int64_t p = std::int64_t{a.raw_} * b.raw_;
      // Rounding the magnitude: ties away from zero, or toward zero when half = 0.
      const std::int64_t r = p >= 0 ? (p + half) >> FracBits : -((half - p) >> FracBits);
      return make(static_cast<Storage>(r > raw_max ? raw_max : (r < raw_min ? raw_min : r)));
    } else {
      // Wider int64 formats: a 128-bit magnitude, <= 2^126 plus the rounding half.
      const detail::u128 product = detail::mul_64x64(detail::magnitude(a.raw_), detail::magnitude(b.raw_));
      const detail::u128 scaled = detail::shr_rounded(product, FracBits, mode);
      return make(static_cast<Storage>(detail::saturate_signed((a.raw_ < 0) != (b.raw_ < 0), scaled, max_magnitude)));
    }
  }

  static constexpr q divide(q a, q b, rounding mode) {
    if (b.raw_ == 0) return a.raw_ > 0 ? max() : (a.raw_ < 0 ? min() : q{});
    // Numerator |a| * 2^F <= 2^(magnitude_bits + FracBits): <= 2^62 for int16/int32 formats.
    using wide = detail::wide_for<magnitude_bits + FracBits>;
    const bool negative = (a.raw_ < 0) != (b.raw_ < 0);
    const std::uint64_t den = detail::magnitude(b.raw_);
    const detail::quotient d = detail::divide(detail::shl(detail::widen<wide>(detail::magnitude(a.raw_)), FracBits), den);
    if (d.overflow) return negative ? min() : max();
    // Half-up on the magnitude: rem >= den / 2 exactly when rem >= den - rem (rem < den, no overflow).
    const bool round_up = mode == rounding::nearest && d.rem >= den - d.rem;
    // A u128 magnitude absorbs the carry of quot = 2^64 - 1; a uint64 quot is <= 2^62 here.
    const wide mag = detail::add(detail::widen<wide>(d.quot), round_up ? 1u : 0u);
    return make(static_cast<Storage>(detail::saturate_signed(negative, mag, max_magnitude)));
  }

  static constexpr q convert(double x, rounding mode) {
    if (x != x) return q{};  // NaN -> 0
    // Scaling by a power of two is exact unless it overflows to +-inf, which saturates below.
    const double scaled = x * raw_scale;
    if (scaled >= raw_limit) return max();
    if (scaled <= -raw_limit) return min();
    const double abs_scaled = scaled < 0 ? -scaled : scaled;
    // abs_scaled < 2^63, so it converts; truncation toward zero.
    std::uint64_t mag = static_cast<std::uint64_t>(abs_scaled);
    // abs_scaled - mag is exact (mag is the integer part of a double), so the tie test is exact.
    if (mode == rounding::nearest && abs_scaled - static_cast<double>(mag) >= 0.5) ++mag;
    return make(static_cast<Storage>(detail::saturate_signed(scaled < 0, mag, max_magnitude)));
  }
};

// Conversion between formats, rounded by Mode and saturating.
template <typename To, rounding Mode = rounding::nearest, int I, int F, typename S>
constexpr To q_cast(q<I, F, S> x) {
  constexpr int shift = To::frac_bits - F;  // |shift| <= 63
  const bool negative = x.raw() < 0;
  const std::uint64_t mag = detail::magnitude(x.raw());  // <= 2^(I + F)
  std::int64_t raw = 0;
  if constexpr (shift >= 0) {
    using wide = detail::wide_for<I + F + shift>;  // mag * 2^shift <= 2^(I + F + shift)
    raw = detail::saturate_signed(negative, detail::shl(detail::widen<wide>(mag), shift), To::max_magnitude);
  } else {
    using wide = detail::wide_for<I + F>;
    raw = detail::saturate_signed(negative, detail::shr_rounded(detail::widen<wide>(mag), -shift, Mode),
                                  To::max_magnitude);
  }
  return To::from_raw(static_cast<typename To::storage>(raw));
}

template <typename To, int I, int F, typename S>
constexpr To q_cast_trunc(q<I, F, S> x) {
  return q_cast<To, rounding::toward_zero>(x);
}

// Common formats of the pipeline.
using q16 = q<15, 16>;  // positions, Q15.16
using q30 = q<1, 30>;   // unit-range factors

// Proofs of the documented policies, checked by every compiler that includes this.
static_assert(q16::from_double(0.5).raw() == 1 << 15);
static_assert(q16::from_double(-0.5).raw() == -(1 << 15));
static_assert(q16::from_double(1.5 / 65536).raw() == 2 && q16::from_double(-1.5 / 65536).raw() == -2);  // ties away
static_assert(q16::from_double_trunc(1.75 / 65536).raw() == 1);
static_assert(q16::from_double(1e30) == q16::max() && q16::from_double(-1e30) == q16::min());
static_assert(q16::from_double(std::numeric_limits<double>::quiet_NaN()) == q16{});
static_assert(q16::from_double(std::numeric_limits<double>::infinity()) == q16::max());
static_assert(q16::max() + q16::lsb() == q16::max() && q16::min() - q16::lsb() == q16::min());
static_assert(wrapping_add(q16::max(), q16::lsb()) == q16::min());
static_assert(-q16::min() == q16::max());
static_assert(q16::from_int(3) * q16::from_double(0.5) == q16::from_double(1.5));
static_assert(q16::from_int(1) / q16{} == q16::max() && q16::from_int(-1) / q16{} == q16::min());
static_assert(q_cast<q30>(q16::from_double(0.25)) == q30::from_double(0.25));
static_assert(q_cast<q16>(q30::from_raw(1 << 13)).raw() == 1 && q_cast_trunc<q16>(q30::from_raw(1 << 13)).raw() == 0);

}  // namespace fixedpoint
