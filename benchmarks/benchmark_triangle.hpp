// One perspective triangle for the kernel benchmarks: a floor seen at a
// slant, near vertices at w = 2, the far one at w = 10, covering about a
// third of a 320x240 frame, textured with 128 texels per unit of uv.
#pragma once

#include <cstdint>

#include "spanlight/1_vertex/project.hpp"
#include "spanlight/2_triangle/attributes.hpp"
#include "spanlight/2_triangle/setup.hpp"

namespace benchmarks {

inline constexpr int width = 320, height = 240;

constexpr spanlight::Vec4Wide clip(double x, double y, double z, double w) {
  constexpr double one = 4294967296.0;  // Q31.32
  return {static_cast<std::int64_t>(x * one), static_cast<std::int64_t>(y * one), static_cast<std::int64_t>(z * one),
          static_cast<std::int64_t>(w * one)};
}

inline const spanlight::Vec4Wide corners[3] = {clip(-2.0, -0.8, 1.5, 2.0), clip(2.0, -0.8, 1.5, 2.0), clip(0.0, 0.6, 9.5, 10.0)};

inline spanlight::TriangleSetup floor_setup() {
  const spanlight::ScreenVertex screen[3] = {spanlight::project(corners[0], width, height),
                                             spanlight::project(corners[1], width, height),
                                             spanlight::project(corners[2], width, height)};
  spanlight::TriangleSetup setup{};
  spanlight::setup_triangle(screen, spanlight::Cull::none, height, setup);
  return setup;
}

// uv in texels * 2^16 (128 texels per unit), one projector with q growing with distance.
inline spanlight::TriangleAttributes<1> floor_attributes(const spanlight::TriangleSetup& setup) {
  const std::int32_t u[3] = {0, 128 << 16, 64 << 16}, v[3] = {0, 0, 512 << 16};
  const std::int32_t proj[3][4] = {{1 << 27, 1 << 27, 1 << 28, 1 << 28}, {3 << 27, 1 << 27, 1 << 28, 1 << 28}, {1 << 28, 3 << 27, 1 << 28, 3 << 28}};
  spanlight::TriangleAttributes<1> a{};
  const int o0 = setup.order[0], o1 = setup.order[1], o2 = setup.order[2];
  a.u0 = u[o0];
  a.du1 = u[o1] - u[o0];
  a.du2 = u[o2] - u[o0];
  a.v0 = v[o0];
  a.dv1 = v[o1] - v[o0];
  a.dv2 = v[o2] - v[o0];
  for (int c = 0; c < 4; ++c) {
    a.proj0[0][c] = proj[o0][c];
    a.proj_d1[0][c] = proj[o1][c] - proj[o0][c];
    a.proj_d2[0][c] = proj[o2][c] - proj[o0][c];
  }
  return a;
}

}  // namespace benchmarks
