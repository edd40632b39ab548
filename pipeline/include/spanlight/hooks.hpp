// Hooks: where tests, benchmarks and firmware look into a frame without a
// second copy of the frame plan. render_frame calls them at fixed points;
// NoHooks compiles to nothing. A type with only some of them derives from
// NoHooks and hides the rest.
#pragma once

#include <cstdint>
#include <type_traits>

namespace spanlight {

enum class Pass : std::uint8_t { shadow_depth, depth_ambient, light, modulate, fused };

struct NoHooks {
  // A pass over the scene begins or ends; projector is the light's index, or -1.
  static constexpr void pass_begin(Pass, int /*projector*/) {}
  static constexpr void pass_end(Pass, int /*projector*/) {}
  // A pass wrote pixel `index` of its target (colour, depth or a shadow map).
  static constexpr void touched(Pass, std::uint32_t /*index*/) {}
  // A triangle's way from its vertices to its spans begins, and its rows begin (setup done).
  static constexpr void triangle_begin() {}
  static constexpr void triangle_rows() {}
  // A band of rows [first_row, first_row + rows) is finished in the target's colour buffer
  // (rows laid out from its start): push it to a display now.
  template <typename Storage>
  static constexpr void band_done(std::uint16_t /*first_row*/, std::uint16_t /*rows*/, const Storage* /*colour*/) {}
};

// Whether H watches pixels (its own touched): else a pass may skip the call altogether.
template <typename H>
constexpr bool sees_pixels() {
  using Plain = std::remove_cvref_t<H>;
  if constexpr (requires { static_cast<void (*)(Pass, std::uint32_t)>(&Plain::touched); })
    return static_cast<void (*)(Pass, std::uint32_t)>(&Plain::touched) != &NoHooks::touched;
  else return true;
}

}  // namespace spanlight
