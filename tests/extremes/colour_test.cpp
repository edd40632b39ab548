// Colour and shadow-compare extremes: light summing far above 1 saturates;
// shadow bias 0 and very large biases behave as the spec's condition 4,
// r/q - bias <= D, says.
#include <catch2/catch.hpp>

#include <cmath>

#include "extremes_support.hpp"

using namespace spanlight::xt;

namespace {

constexpr int tolerance = 3;

// A floor and an occluder above it, lit from above by one shadowed projector.
sc::Scene shadow_scene(double bias, sc::ShadowFilter filter, bool shadows = true) {
  sc::Scene s = make_scene(128, 128, {0.5, 7, 4}, {0, 0, 0}, {0, 1, 0}, 55.0, 1.0, 30.0);
  s.ambient = glm::dvec3(0.2);
  s.textures.push_back(texture("white", solid_image(1, 1, {255, 255, 255}), sc::Filter::nearest, sc::Wrap::clamp));
  s.objects.push_back(quad("floor", {glm::dvec3(-5, 0, 5), glm::dvec3(5, 0, 5), glm::dvec3(5, 0, -5), glm::dvec3(-5, 0, -5)},
                           glm::dvec3(0.9, 0.9, 0.9)));
  s.objects.push_back(quad("occluder", {glm::dvec3(-1, 1.5, 1), glm::dvec3(1, 1.5, 1), glm::dvec3(1, 1.5, -1), glm::dvec3(-1, 1.5, -1)},
                           glm::dvec3(0.8, 0.3, 0.3)));
  sc::Projector p = projector({1, 6, 1}, {0, 0, 0}, {0, 1, 0}, 70.0, 1.0, 20.0, 0, glm::dvec3(0.7));
  if (shadows) p.shadows = sc::Shadows{256, bias, filter};
  s.projectors.push_back(p);
  return s;
}

}  // namespace

TEST_CASE("light summing far above 1 saturates to the surface colour", "[extremes][colour]") {
  // Ambient 0.9 plus three projectors of colour 4, 300 and 1e6 (the spec puts
  // no upper bound on a projector's colour; prepare keeps it as Q8.8 and
  // saturates at 255.996, which changes nothing here: any non-zero texel,
  // >= 1/255, times a colour >= 255 already reaches 1). Images: white, a
  // level-1 grey and a black-and-white checker: a pixel lit by any non-black
  // texel must show exactly its surface colour, and the black texels add nothing.
  sc::Scene s = make_scene(96, 96, {0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45.0, 1.0, 20.0);
  s.ambient = glm::dvec3(0.9);
  s.textures.push_back(texture("white", solid_image(1, 1, {255, 255, 255}), sc::Filter::nearest, sc::Wrap::clamp));
  // nearest: a bilinear blend of this image with the black border would make
  // fractions of a level, which the fixed pipeline rounds before scaling by
  // the colour (see the  case below).
  s.textures.push_back(texture("level1", solid_image(2, 2, {1, 1, 1}), sc::Filter::nearest, sc::Wrap::clamp));
  s.textures.push_back(texture("checker", checker_image(4, 4, 1, {255, 255, 255}, {0, 0, 0}), sc::Filter::nearest, sc::Wrap::clamp));
  s.textures.push_back(texture("surface", checker_image(8, 8, 2, {250, 120, 30}, {20, 90, 240}), sc::Filter::bilinear, sc::Wrap::repeat));
  sc::Object square = quad("square", {glm::dvec3(-2, -2, 0), glm::dvec3(2, -2, 0), glm::dvec3(2, 2, 0), glm::dvec3(-2, 2, 0)},
                           glm::dvec3(1.0, 0.8, 0.6));
  square.texture = 3;
  s.objects.push_back(square);
  s.projectors.push_back(projector({-1, 0, 5}, {-1, 0, 0}, {0, 1, 0}, 20.0, 1.0, 20.0, 0, glm::dvec3(4.0)));
  s.projectors.push_back(projector({0.5, 0.8, 5}, {0.5, 0.8, 0}, {0, 1, 0}, 15.0, 1.0, 20.0, 1, glm::dvec3(300.0)));
  s.projectors.push_back(projector({0.8, -0.9, 5}, {0.8, -0.9, 0}, {0, 1, 0}, 18.0, 1.0, 20.0, 2, glm::dvec3(1e6)));
  snap_positions_to_q16(s);
  // The bare surface: ambient 1 and no projector gives light 255 everywhere.
  sc::Scene bare = s;
  bare.ambient = glm::dvec3(1.0);
  bare.projectors.clear();
  const pr::FixedFrame surface = pr::render_fixed(*pr::prepare_scene(bare), default_options());
  for (const bool fused : {false, true}) {
    const spanlight::Knobs o = with_passes(default_options(), fused);
    const Both b = render_both(s, o);
    dump(b, fused ? "saturate_fused" : "saturate");
    const Agreement a = agree(b, 1, tolerance);
    // Where the float model's light saturated (at the pixel and its 8 neighbours:
    // the frustum's sides are edges), the fixed pixel is its bare surface, bit for bit.
    int saturated = 0, not_bare = 0;
    const int w = s.width;
    for (int y = 1; y + 1 < s.height; ++y)
      for (int x = 1; x + 1 < w; ++x) {
        bool all = true;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const auto j = static_cast<std::size_t>((y + dy) * w + x + dx);
            all = all && b.ref.object[j] >= 0 && b.ref.light_rgb[j * 3] >= 1.0f && b.ref.light_rgb[j * 3 + 2] >= 1.0f;
          }
        if (!all) continue;
        const auto i = static_cast<std::size_t>(y * w + x);
        ++saturated;
        not_bare += channel_diff(b.fixed.rgb, surface.rgb, i, i) != 0;
      }
    INFO((fused ? "fused: " : "multipass: ") << describe(a, s.width) << "; saturated px " << saturated
                                             << ", of them not the bare surface: " << not_bare);
    CHECK(a.unexplained == 0);
    CHECK(saturated > 1500);
    CHECK(not_bare == 0);
  }
}

TEST_CASE("a bright projector over a dim bilinear image: light within 3 levels of the float model",
          "[extremes][colour]") {
  // Regression (found by this suite, fixed; docs/limits.md): the projector's light samples the image
  // with a bilinear fetch, which rounds the blended texel to 8 bits (Rgb8),
  // and only then multiplies by the projector's colour (Q8.8) and the shadow
  // factor. The rounding error, up to 0.5 level, is multiplied by the
  // colour: up to 8 levels of light at colour 16, 150 at colour 300 (where a
  // corner of the frustum blends a level-1 image with the black border to
  // 0.25 level, the fixed pipeline rounds it to 0 and draws no light, the
  // float model 0.29). The spec bounds a projector's colour only below (>= 0).
  // The fix: sample the projector image without the final rounding (the
  // blend times 2^16, as 4_pixel/texture.hpp's Texel16 describes) and round once after
  // colour * blend * shadow: (colour * blend16 * shadow + 2^31) >> 32, a
  // product below 2^49.
  // Here: colour 16 over a 4x4 ramp of levels 0..15, ambient 0, white
  // surface: light = 16 * level / 255 in [0, 0.94], smooth across the wall.
  sc::Scene s = make_scene(128, 128, {0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45.0, 1.0, 20.0);
  sc::Image ramp{4, 4, {}};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const auto level = static_cast<std::uint8_t>(y * 4 + x);
      ramp.rgb.insert(ramp.rgb.end(), {level, level, level});
    }
  s.textures.push_back(texture("ramp", ramp, sc::Filter::bilinear, sc::Wrap::clamp));
  s.objects.push_back(quad("wall", {glm::dvec3(-3, -3, 0), glm::dvec3(3, -3, 0), glm::dvec3(3, 3, 0), glm::dvec3(-3, 3, 0)}));
  s.projectors.push_back(projector({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 30.0, 1.0, 20.0, 0, glm::dvec3(16.0)));
  snap_positions_to_q16(s);
  const Both b = render_both(s);
  dump(b, "bright_projector");
  const Agreement a = agree(b, 0, tolerance);
  INFO(describe(a, s.width));
  CHECK(a.covered_ref == s.width * s.height);
  CHECK(a.stats.max_abs_lsb <= tolerance);
}

TEST_CASE("a bias of 1 or more lights everything: the same picture as without shadows", "[extremes][colour][shadow]") {
  // r/q <= 1 inside the frustum and D >= 0, so r/q - bias <= 0 <= D for any
  // bias >= 1. Prepare keeps the bias as Q1.30 clamped to 1.99 (prepare.cpp),
  // which is still >= 1: the same result for bias 1.5, 2 and 1e6.
  for (const double bias : {1.0, 1.5, 2.0, 1e6}) {
    for (const sc::ShadowFilter filter : {sc::ShadowFilter::nearest, sc::ShadowFilter::pcf2x2}) {
      sc::Scene s = shadow_scene(bias, filter);
      sc::Scene unshadowed = shadow_scene(bias, filter, false);
      snap_positions_to_q16(s);
      snap_positions_to_q16(unshadowed);
      const Both b = render_both(s);
      const Both u = render_both(unshadowed);
      INFO("bias " << bias << ", " << (filter == sc::ShadowFilter::nearest ? "nearest" : "pcf2x2"));
      CHECK(pixels_differing(b.fixed.rgb, u.fixed.rgb, 0) == 0);
      CHECK(pixels_differing(b.ref.rgb, u.ref.rgb, 0) == 0);
      const Agreement a = agree(b, 1, tolerance);
      INFO(describe(a, s.width));
      CHECK(a.unexplained == 0);
    }
  }
}

TEST_CASE("bias 0: shadows still fall where they should - self-shadowing is the documented trade", "[extremes][colour][shadow]") {
  // With bias 0 a surface compares its own r/q with the depth the map stored
  // for it: equal in real arithmetic, so either side of the compare in
  // practice. The map keeps the top 24 bits of the depth by truncation
  // (4_pixel/depth.hpp, DepthFormat::store), which puts D up to one step below the
  // surface's own r/q: lit surfaces may shadow themselves ("acne") where the
  // r/q interpolated at the pixel exceeds the truncated D. What must hold:
  //  - the occluder's shadow on the floor (the floor is > 0.2 window-depth
  //    behind the occluder there) is dark in both renderers;
  //  - the directly lit occluder top and floor are lit or self-shadowed, never
  //    anything in between (nearest filter), in both.
  // The lit fraction of the floor is reported for docs/limits.md.
  sc::Scene s = shadow_scene(0.0, sc::ShadowFilter::nearest);
  snap_positions_to_q16(s);
  const Both b = render_both(s);
  dump(b, "bias0");
  sc::Scene biased = shadow_scene(0.002, sc::ShadowFilter::nearest);
  snap_positions_to_q16(biased);
  const Both good = render_both(biased);
  const Agreement a_good = agree(good, 2, tolerance);
  INFO("bias 0.002: " << describe(a_good, s.width));
  CHECK(a_good.unexplained == 0);

  const int lit_level = fm::to_byte(0.9 * 0.9), dark_level = fm::to_byte(0.2 * 0.9);
  int floor_px = 0, in_shadow = 0, shadow_dark_fixed = 0, shadow_dark_ref = 0, lit_px = 0, lit_fixed = 0, lit_ref = 0,
      in_between = 0;
  for (std::size_t i = 0; i < b.ref.object.size(); ++i) {
    if (b.ref.object[i] != 0) continue;
    ++floor_px;
    const int fixed_r = b.fixed.rgb[i * 3], ref_r = b.ref.rgb[i * 3], good_r = good.ref.rgb[i * 3];
    in_between += std::abs(fixed_r - lit_level) > tolerance && std::abs(fixed_r - dark_level) > tolerance &&
                  std::abs(fixed_r - fm::to_byte(0.2 * 0.9)) > tolerance;
    if (good_r <= dark_level + tolerance && good.ref.light_rgb[i * 3] < 0.25f) {
      // In the occluder's shadow (per the well-biased reference) and inside the frustum.
      ++in_shadow;
      shadow_dark_fixed += fixed_r <= dark_level + tolerance;
      shadow_dark_ref += ref_r <= dark_level + tolerance;
    } else if (good_r >= lit_level - tolerance) {
      ++lit_px;
      lit_fixed += fixed_r >= lit_level - tolerance;
      lit_ref += ref_r >= lit_level - tolerance;
    }
  }
  INFO("floor " << floor_px << " px; in the occluder's shadow " << in_shadow << " (dark: fixed " << shadow_dark_fixed
                << ", float " << shadow_dark_ref << "); directly lit " << lit_px << " (still lit at bias 0: fixed "
                << lit_fixed << ", float " << lit_ref << "); neither colour " << in_between);
  CHECK(in_shadow > 500);
  CHECK(shadow_dark_fixed >= in_shadow - in_shadow / 50);
  CHECK(shadow_dark_ref >= in_shadow - in_shadow / 50);
  CHECK(lit_px > 3000);
  CHECK(in_between <= floor_px / 100);  // outline pixels of the frustum and the shadow
}
