// The renderers the effect tests run, each with the error bounds it states. A test
// builds a scene whose picture is known, renders it with every renderer here and
// checks the picture within that renderer's bounds.
//
// To add a renderer (the fixed-point pipeline: prepare::prepare_scene, then
// prepare::render_fixed), append an entry in effects_renderers.cpp with its render
// function and its derived bounds; every effect test then runs it.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace spanlight::effects {

struct Picture {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // top row first
  std::uint8_t channel(int x, int y, int c) const {
    return rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3 +
               static_cast<std::size_t>(c)];
  }
};

struct EffectRenderer {
  std::string name;
  std::function<Picture(const scene::Scene&)> render;
  // |output byte - round(255 * exact value)| where the exact value is known (no texel or
  // depth decision within the error below is involved).
  int value_lsb;
  // Error of an interpolated texture coordinate, in texels (u * width, s/q * width, the
  // falloff texel r/q * width): pixels whose exact coordinate lies this close to a texel
  // boundary are not checked, the renderer may pick either texel there.
  double texel_coordinate_error;
  // Error of the mipmap level of detail lambda against the exact rule.
  double lambda_error;
  // Fraction of pixels that may change when camera and scene move rigidly together
  // (coverage and depth-compare ties decided by rounding).
  double rigid_motion_pixel_fraction;
};

const std::vector<EffectRenderer>& effect_renderers();

}  // namespace spanlight::effects
