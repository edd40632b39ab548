// What a scene uses, known at compile time, so what it does not use is not
// compiled (tgx's idea): a firmware build bakes one Features type; the host
// tools instantiate the full one. Runtime knobs that cost nothing to keep
// dynamic (span length, depth bits) live in Precision.
#pragma once

#include <cstdint>

#include "fixedpoint/reciprocal.hpp"
#include "spanlight/pixel_inline.hpp"

namespace spanlight {

// Calls fn(j) for each projector j in [begin, end). Unrolled over the
// compile-time maximum N, so j is a constant in each copy and a walk's
// per-projector values stay in registers instead of an array indexed at run time.
template <int N, typename Fn>
[[gnu::always_inline]] inline void for_each_projector(int begin, int end, Fn&& fn) {
  for (int j = 0; j < N; ++j) {
    if (j >= begin && j < end) fn(j);
  }
}

enum class PixelFormat : std::uint8_t { rgb888, rgb565 };

// The divide of the perspective step: table lookup plus Newton steps.
template <int TableBits, int NewtonSteps>
struct TableReciprocal {
  static constexpr int table_bits = TableBits;
  static constexpr int newton_steps = NewtonSteps;
  static constexpr fixedpoint::Reciprocal of(std::uint32_t d) {
    return fixedpoint::reciprocal<TableBits, NewtonSteps>(d);
  }
  // 2^62 / m for m already in [2^31, 2^32): of(m) without the CLZ (a libgcc call on ARMv6-M).
  static constexpr std::uint32_t of_normalised(std::uint32_t m) {
    return fixedpoint::reciprocal_normalised<TableBits, NewtonSteps>(m);
  }
};

template <int MaxProjectors, bool Shadows, bool Pcf, bool Bilinear, PixelFormat Format, typename Reciprocal>
struct Features {
  static constexpr int max_projectors = MaxProjectors;  // 0 links no projector code at all
  static constexpr bool shadows = Shadows;              // shadow maps and the depth compare
  static constexpr bool pcf = Pcf;                      // pcf2x2 filter present (else nearest only)
  static constexpr bool bilinear = Bilinear;            // some texture uses bilinear
  static constexpr PixelFormat format = Format;
  using reciprocal = Reciprocal;
};

// The host tools' build: everything on, up to four projectors.
template <PixelFormat Format, typename Reciprocal>
using HostFeaturesWith = Features<4, true, true, true, Format, Reciprocal>;
template <PixelFormat Format, int TableBits, int NewtonSteps>
using HostFeatures = HostFeaturesWith<Format, TableReciprocal<TableBits, NewtonSteps>>;

struct Precision {
  std::uint8_t span_log2 = 4;    // a reciprocal every 2^span_log2 pixels; 0 = every pixel
  std::uint8_t span_tolerance_log2 = 3;  // shorten segments that would drift > 1/8 texel; 0: never; at most 10
  std::uint8_t depth_bits = 24;  // 16 or 24: bits kept in the depth buffer and shadow maps
  bool fused = false;            // one pass per pixel instead of the paper's multipass
};

}  // namespace spanlight
