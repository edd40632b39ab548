// Sizes: 1x1 and 4096x4096 output, 1x1 and 4096x4096 textures (made in
// memory), shadow maps from 8^2 to 4096^2.
//
// The 4096x4096 output is rendered once per build (plain and sanitizer twin),
// by the fixed pipeline only: the float model keeps ~90 bytes per pixel
// (1.5 GB at that size), so coverage and colour are checked against the
// coverage rule itself on every 64th row, and the snapped vertices against
// their exact projection. The 4096^2 shadow map and texture cases run in the
// plain build only (the float model's 4096^2 map alone is 128 MB of doubles
// and takes seconds under the sanitizers); the twin runs the 2048^2 ones.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "extremes_support.hpp"

using namespace spanlight::xt;

namespace {

constexpr int tolerance = 3;

sc::Scene small_scene(int width, int height) {
  sc::Scene s = make_scene(width, height, {0.5, 2, 5}, {0, 0, 0}, {0, 1, 0}, 50.0, 0.5, 50.0);
  s.ambient = glm::dvec3(0.3);
  s.textures.push_back(texture("slide", checker_image(8, 8, 2, {255, 200, 150}, {80, 120, 255}), sc::Filter::nearest,
                               sc::Wrap::clamp));
  s.objects.push_back(quad("floor", {glm::dvec3(-4, 0, 4), glm::dvec3(4, 0, 4), glm::dvec3(4, 0, -4), glm::dvec3(-4, 0, -4)},
                           glm::dvec3(0.9, 0.9, 0.8)));
  s.objects.push_back(quad("card", {glm::dvec3(-1, 0.2, 0.5), glm::dvec3(1, 0.2, 0.5), glm::dvec3(1, 1.7, 0.0), glm::dvec3(-1, 1.7, 0.0)},
                           glm::dvec3(0.3, 0.8, 0.4)));
  s.projectors.push_back(projector({2, 4, 2}, {0, 0, 0}, {0, 1, 0}, 40.0, 1.0, 20.0, 0, glm::dvec3(0.6)));
  return s;
}

}  // namespace

TEST_CASE("1x1, 1x4096 and 4096x1 outputs agree with the float model", "[extremes][sizes]") {
  // fovy 60: P's x scale is cot(30 deg) / aspect = 1.73 * 4096 = 7094 for
  // 1x4096, under prepare's 2^13 (at fovy < 53 degrees it is refused: see below).
  for (const auto& [w, h] : {std::pair{1, 1}, std::pair{1, 4096}, std::pair{4096, 1}, std::pair{2, 3}}) {
    sc::Scene s = small_scene(w, h);
    s.camera.fovy_deg = 60.0;
    snap_positions_to_q16(s);
    const Both b = render_both(s);
    const Agreement a = agree(b, 1, tolerance);
    INFO(w << "x" << h << ": " << describe(a, w));
    CHECK(a.unexplained == 0);
    if (w * h == 1) {
      // The single pixel's centre is the middle of the view: the card or the floor.
      CHECK(a.covered_fixed == 1);
      CHECK(a.over_tolerance == 0);
    }
  }
}

TEST_CASE("an output of 1x4096 with fovy below 53 degrees is refused by prepare, not drawn wrong", "[extremes][sizes]") {
  // cot(fovy / 2) * 4096 >= 2^13 when fovy <= 2 atan(1/2) = 53.13 degrees.
  // An axis-aligned camera, so that entry of P * V is cot(fovy / 2) / aspect itself.
  sc::Scene s = small_scene(1, 4096);
  s.camera.eye = {0, 0, 5};
  s.camera.target = {0, 0, 0};
  s.camera.fovy_deg = 53.0;
  CHECK_THROWS_AS(pr::prepare_scene(s), pr::PrepareError);
  s.camera.fovy_deg = 53.3;
  CHECK_NOTHROW(pr::prepare_scene(s));
}

TEST_CASE("4096x4096 output: one render, checked on sampled rows against the coverage rule", "[extremes][sizes]") {
  sc::Scene s = make_scene(4096, 4096, {0, 0, 6}, {0, 0, 0}, {0, 1, 0}, 40.0, 1.0, 20.0);
  s.ambient = glm::dvec3(0.4);
  // Three flat triangles that do not overlap on screen, one of them a sliver,
  // covering about a quarter of the frame.
  s.objects.push_back(triangle("big", {glm::dvec3(-1.9, -1.7, 0), glm::dvec3(1.3, -1.1, -0.5), glm::dvec3(-0.2, 1.8, 0.4)},
                               glm::dvec3(0.9, 0.5, 0.2)));
  s.objects.push_back(triangle("small", {glm::dvec3(1.2, 1.2, 0.5), glm::dvec3(1.25, 1.3, 0.5), glm::dvec3(1.19, 1.31, 0.5)},
                               glm::dvec3(0.2, 0.6, 0.9)));
  s.objects.push_back(triangle("sliver", {glm::dvec3(-2.1, 2.0, 0.2), glm::dvec3(2.05, 1.95, 0.2), glm::dvec3(0.0, 1.9771, 0.2)},
                               glm::dvec3(0.5, 0.9, 0.5)));
  snap_positions_to_q16(s);
  const auto prepared = pr::prepare_scene(s);
  const pr::FixedFrame f = pr::render_fixed(*prepared, default_options());
  const std::uint32_t clear = spanlight::depth_clear(24);

  // Snapped vertices: within 1/512 px + 2^-7 subpixel of the exact projection (project.hpp).
  std::vector<std::array<fm::SnappedVertex, 3>> snapped;
  const glm::dmat4 vp = sc::camera_view_projection(s);
  double worst = 0;
  for (std::uint16_t o = 0; o < prepared->scene.object_count; ++o) {
    const spanlight::ObjectData& object = prepared->scene.objects[o];
    std::array<fm::SnappedVertex, 3> tri{};
    for (std::uint32_t k = 0; k < 3; ++k) {
      const spanlight::ScreenVertex v =
          spanlight::project(spanlight::transform(prepared->matrices.clip_from_object[o], object.positions + object.indices[k] * 3), 4096, 4096);
      tri[k] = {v.x, v.y};
      const fm::WindowPoint exact = fm::to_window(vp * glm::dvec4(s.objects[o].mesh.positions[object.indices[k]], 1.0), 4096, 4096);
      worst = std::max({worst, std::fabs(v.x / 256.0 - exact.x), std::fabs(v.y / 256.0 - exact.y)});
    }
    snapped.push_back(tri);
  }
  INFO("largest snapped-vertex error " << worst << " px");
  CHECK(worst <= 1.0 / 512.0 + 1.0 / 32768.0);

  // Every 64th row (and the last): covered exactly where the rule says, in the
  // colour of the nearest triangle covering it (ambient x object colour).
  int checked = 0, wrong_coverage = 0, wrong_colour = 0, covered = 0;
  for (int y = 0; y < 4096; y = (y == 4095 ? 4096 : std::min(y + 64, 4095))) {
    for (int x = 0; x < 4096; ++x) {
      int front = -1;
      for (std::size_t o = 0; o < snapped.size(); ++o)
        if (fm::pixel_covered(snapped[o].data(), x, y)) front = static_cast<int>(o);
      const auto i = static_cast<std::size_t>(y) * 4096 + static_cast<std::size_t>(x);
      const bool drawn = f.depth[i] != clear;
      ++checked;
      covered += drawn;
      wrong_coverage += drawn != (front >= 0);
      if (front >= 0 && drawn) {
        const glm::dvec3 c = s.ambient * s.objects[static_cast<std::size_t>(front)].color;
        for (int ch = 0; ch < 3; ++ch) wrong_colour += std::abs(int{f.rgb[i * 3 + static_cast<std::size_t>(ch)]} - fm::to_byte(c[ch])) > 2;
      }
    }
  }
  INFO(checked << " pixels checked, " << covered << " covered; wrong coverage " << wrong_coverage << ", wrong colour "
               << wrong_colour);
  CHECK(covered > checked / 10);
  CHECK(wrong_coverage == 0);
  CHECK(wrong_colour == 0);
}

TEST_CASE("1x1 and 4096x4096 textures, on surfaces and in projectors", "[extremes][sizes]") {
  // The 4096^2 texture is a smooth ramp (one level per 16 texels), so neither
  // minification nor the 1/8-texel span drift can move a pixel by more than
  // the rounding tolerance; it is shown whole (minified 32x) and a 64-texel
  // window of it magnified, with repeat, clamp and border.
  const int big = sanitized ? 2048 : 4096;
  sc::Image ramp{big, big, {}};
  ramp.rgb.reserve(static_cast<std::size_t>(big) * static_cast<std::size_t>(big) * 3);
  for (int y = 0; y < big; ++y)
    for (int x = 0; x < big; ++x)
      ramp.rgb.insert(ramp.rgb.end(), {static_cast<std::uint8_t>(x * 255 / (big - 1)), static_cast<std::uint8_t>(y * 255 / (big - 1)),
                                       static_cast<std::uint8_t>(128)});
  for (const sc::Wrap wrap : {sc::Wrap::repeat, sc::Wrap::clamp, sc::Wrap::border}) {
    for (const bool magnified : {false, true}) {
      sc::Scene s = make_scene(128, 128, {0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 30.0, 1.0, 10.0);
      s.ambient = glm::dvec3(0.5);
      s.textures.push_back(texture("ramp", ramp, sc::Filter::bilinear, wrap));
      s.textures.push_back(texture("one", solid_image(1, 1, {200, 150, 255}), sc::Filter::bilinear, wrap));
      const double u0 = magnified ? 0.4 : -0.1, u1 = magnified ? 0.4 + 64.0 / big : 1.1;  // beyond [0, 1] when minified
      sc::Object square = quad("square", {glm::dvec3(-1, -1, 0), glm::dvec3(0.2, -1, 0), glm::dvec3(0.2, 1, 0), glm::dvec3(-1, 1, 0)},
                               glm::dvec3(1.0), {glm::dvec2(u0, u0), glm::dvec2(u1, u0), glm::dvec2(u1, u1), glm::dvec2(u0, u1)});
      square.texture = 0;
      sc::Object small = quad("small", {glm::dvec3(0.3, -1, 0), glm::dvec3(1, -1, 0), glm::dvec3(1, 1, 0), glm::dvec3(0.3, 1, 0)},
                              glm::dvec3(1.0), {glm::dvec2(-3, -2), glm::dvec2(5, -2), glm::dvec2(5, 7), glm::dvec2(-3, 7)});
      small.texture = 1;  // 1x1: every uv shows the one texel (border: black outside [0, 1])
      s.objects.push_back(square);
      s.objects.push_back(small);
      // The ramp as a projector image too, and the 1x1 texel as another.
      s.projectors.push_back(projector({0, 0, 3}, {0, 0, 0}, {0, 1, 0}, 40.0, 0.5, 10.0, 0, glm::dvec3(0.4)));
      s.projectors.push_back(projector({0.5, 0.5, 3}, {0.5, 0.5, 0}, {0, 1, 0}, 20.0, 0.5, 10.0, 1, glm::dvec3(0.3)));
      snap_positions_to_q16(s);
      const Both b = render_both(s);
      dump(b, std::string("tex_") + (magnified ? "mag_" : "min_") + std::to_string(static_cast<int>(wrap)));
      const Agreement a = agree(b, 1, tolerance);
      INFO(big << "^2 ramp, wrap " << static_cast<int>(wrap) << (magnified ? ", magnified: " : ", minified: ")
               << describe(a, s.width));
      CHECK(a.covered_ref > 8000);
      CHECK(a.unexplained == 0);
    }
  }
}

TEST_CASE("shadow maps from 8^2 to 4096^2 agree with the float model's", "[extremes][sizes][shadow]") {
  // Camera and projector both look straight down at a floor with a square
  // occluder above it. One map texel covers 2 * 6 * tan(25 deg) / N units of
  // floor, and the camera shows 2 * 10 * tan(25 deg) units over 160 px, so a
  // texel is 160 * 0.6 / N px across (12 px at N = 8). The two renderers'
  // maps may differ in the texels along the occluder's outline (snapping),
  // which moves the shadow's edge by up to one texel: a pixel may differ
  // within that many pixels (plus one) of the reference's shadow edge.
  // The largest map (4096^2; 2048^2 in the sanitizer twin) with `nearest` only: it alone takes ~2 s.
  const int largest = sanitized ? 2048 : 4096;
  for (const int n : {8, 64, 512, largest}) {
    for (const sc::ShadowFilter filter : {sc::ShadowFilter::nearest, sc::ShadowFilter::pcf2x2}) {
      if (n == largest && filter == sc::ShadowFilter::pcf2x2) continue;
      sc::Scene s = make_scene(160, 160, {0.01, 10, 0}, {0, 0, 0}, {0, 0, -1}, 50.0, 1.0, 30.0);
      s.ambient = glm::dvec3(0.2);
      s.textures.push_back(texture("white", solid_image(1, 1, {255, 255, 255}), sc::Filter::nearest, sc::Wrap::clamp));
      s.objects.push_back(quad("floor", {glm::dvec3(-6, 0, 6), glm::dvec3(6, 0, 6), glm::dvec3(6, 0, -6), glm::dvec3(-6, 0, -6)},
                               glm::dvec3(0.9, 0.9, 0.9)));
      s.objects.push_back(quad("occluder", {glm::dvec3(-0.9, 2, 1.1), glm::dvec3(1.3, 2, 0.7), glm::dvec3(1.0, 2, -1.2),
                                            glm::dvec3(-1.1, 2, -0.8)}, glm::dvec3(0.8, 0.3, 0.3)));
      sc::Projector p = projector({0, 6, 0.01}, {0, 0, 0}, {0, 0, -1}, 50.0, 1.0, 20.0, 0, glm::dvec3(0.7));
      p.shadows = sc::Shadows{n, 0.002, filter};
      s.projectors.push_back(p);
      snap_positions_to_q16(s);
      const Both b = render_both(s);
      dump(b, "shadow_" + std::to_string(n) + "_" + std::to_string(static_cast<int>(filter)));
      const int radius = static_cast<int>(std::ceil(160.0 * 0.6 / n)) + 1;
      const Agreement a = agree(b, radius, tolerance);
      // Shadowed pixels in each (light below the lit level).
      int shadow_fixed = 0, shadow_ref = 0;
      for (std::size_t i = 0; i < b.ref.object.size(); ++i) {
        if (b.ref.object[i] != 0) continue;
        shadow_ref += b.ref.rgb[i * 3] < fm::to_byte(0.9 * 0.9) - 10;
        shadow_fixed += b.fixed.rgb[i * 3] < fm::to_byte(0.9 * 0.9) - 10;
      }
      INFO("map " << n << "^2, " << (filter == sc::ShadowFilter::nearest ? "nearest" : "pcf2x2") << ", radius " << radius
                  << ": " << describe(a, s.width) << "; shadowed floor px fixed " << shadow_fixed << ", float " << shadow_ref);
      CHECK(a.unexplained == 0);
      CHECK(shadow_ref > 1000);
      CHECK(std::abs(shadow_fixed - shadow_ref) <= shadow_ref / 20 + 4 * 160 * 0.6 * 4 / n * 4);
    }
  }
}
