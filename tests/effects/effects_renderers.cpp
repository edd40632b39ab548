#include "effects_renderers.hpp"

#include "float_model/float_model.hpp"
#include "prepare/prepare.hpp"
#include "prepare/render_fixed.hpp"
#include "spanlight/knobs.hpp"

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
      // The fixed-point pipeline at the default knobs (knobs.hpp). Values: each projector's light
      // is rounded once to 8 bits (0.5 LSB), and so is the pixel's light times the surface, so a
      // pixel lit by at most two projectors is within 2 LSB; falloff's Q.16 factor adds 2^-15.
      // Coordinates: the span walk keeps each within its tolerance, 2^-5 texel, the rounded steps
      // drift below 2^-6 more, and the sampler truncates to 8 sub-texel bits (2^-8): under 0.051
      // texel (falloff texels counted at the projector image's, as wide or wider here). lambda:
      // held per run within 1/32 + 2^-8.5 of each pixel's (3_span/lod.hpp, tests/mipmap).
      // Rigid motion: the fixed matrices and the 1/256-px snap move an edge or a depth by their
      // rounding; pixels whose centre is that close to an edge or a tie flip: 1 % of a picture.
      {"fixed point",
       [](const scene::Scene& s) {
         const auto prepared = prepare::prepare_scene(s);
         prepare::FixedFrame frame = prepare::render_fixed(*prepared, Knobs{});
         return Picture{frame.width, frame.height, std::move(frame.rgb)};
       },
       2, 0.051, 1.0 / 32 + 0.0028, 0.01},
  };
  return renderers;
}

}  // namespace spanlight::effects
