// The one place where knobs chosen at run time become a compile-time
// configuration: dispatch<Base>(knobs, fn) calls fn.template operator()<F>()
// with F = Base, its pixel format taken from the knobs (and, with
// FixReciprocal, its reciprocal too, so each table and step count gets its own
// direct code, as a baked firmware has). Host tools render any format; the
// firmware bench measures each reciprocal as the firmware would run it.
#pragma once

#include "spanlight/features.hpp"
#include "spanlight/knobs.hpp"

namespace spanlight {

namespace detail {
template <Features F, std::uint8_t TableBits, std::uint8_t Newton>
constexpr Features with_reciprocal() {
  Features f = F;
  f.table_bits = TableBits;
  f.newton = Newton;
  return f;
}
template <Features F, PixelFormat Format>
constexpr Features with_format() {
  Features f = F;
  f.format = Format;
  return f;
}

template <Features F, typename Fn>
decltype(auto) dispatch_reciprocal(const Knobs& k, Fn&& fn) {
  switch (k.table_bits * 4 + k.newton) {
    case 6 * 4 + 0: return fn.template operator()<with_reciprocal<F, 6, 0>()>();
    case 6 * 4 + 1: return fn.template operator()<with_reciprocal<F, 6, 1>()>();
    case 8 * 4 + 0: return fn.template operator()<with_reciprocal<F, 8, 0>()>();
    case 8 * 4 + 1: return fn.template operator()<with_reciprocal<F, 8, 1>()>();
    case 10 * 4 + 0: return fn.template operator()<with_reciprocal<F, 10, 0>()>();
    case 10 * 4 + 1: return fn.template operator()<with_reciprocal<F, 10, 1>()>();
    case 12 * 4 + 0: return fn.template operator()<with_reciprocal<F, 12, 0>()>();
    default: return fn.template operator()<with_reciprocal<F, 12, 1>()>();
  }
}
}  // namespace detail

// ByFormat: the format from the knobs (host tools) or Base's own (firmware).
// ByReciprocal: table bits 6..12 with 0 or 1 Newton steps (the bench's grid;
// the caller refuses others) or Base's own (table_bits 0: the knobs' at run time).
template <Features Base, bool ByFormat, bool ByReciprocal, typename Fn>
decltype(auto) dispatch(const Knobs& k, Fn&& fn) {
  auto next = [&]<Features F>() -> decltype(auto) {
    if constexpr (ByReciprocal) return detail::dispatch_reciprocal<F>(k, fn);
    else return fn.template operator()<F>();
  };
  if constexpr (!ByFormat) return next.template operator()<Base>();
  else switch (k.format) {
    case PixelFormat::rgb565: return next.template operator()<detail::with_format<Base, PixelFormat::rgb565>()>();
    case PixelFormat::rgb565_be: return next.template operator()<detail::with_format<Base, PixelFormat::rgb565_be>()>();
    default: return next.template operator()<detail::with_format<Base, PixelFormat::rgb888>()>();
  }
}

}  // namespace spanlight
