#include "effects_renderers.hpp"

#include "float_model/float_model.hpp"

namespace spanlight::effects {

const std::vector<EffectRenderer>& effect_renderers() {
  static const std::vector<EffectRenderer> renderers = {
      // The float model: double precision with the exact divide at every pixel. A value is a
      // product of a few 8-bit texels and colours, exact to ~1e-15, so round(255 * v) is the
      // exact byte unless 255 * v lies within 1e-12 of a half (the tests' values do not).
      // Coordinates carry ~1e-15 relative rounding: 1e-9 texel covers textures up to 2^20 texels.
      // lambda is the exact rule evaluated in double: log2 of a length with ~1e-15 relative error.
      // Rigid motion moves window positions by ~1e-13 px: a snap or depth tie flips rarely;
      // 0.1 % allows a few pixels of a 64 x 64 picture.
      {"float model",
       [](const scene::Scene& s) {
         float_model::FloatFrame frame = float_model::render_float(s);
         return Picture{frame.width, frame.height, std::move(frame.rgb)};
       },
       0, 1e-9, 1e-9, 0.001},
  };
  return renderers;
}

}  // namespace spanlight::effects
