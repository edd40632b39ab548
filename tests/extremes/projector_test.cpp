// Projectors at their extremes: geometry behind the projector (q < 0), q
// changing sign inside one triangle, surfaces on the projector's near and far
// planes, a projector inside a room with a field of view of 100 to 170 degrees.
//
// Expectation: no unexplained pixel (extremes_support.hpp). The projector's
// s/q, t/q, r/q are exact at span subdivision points and stepped linearly in
// between with a drift below 2^-3 texel of the projector image (3_span/segments.hpp), and
// evaluated at every pixel of a segment where q changes sign; so a light
// boundary (frustum side, q = 0, near or far plane, texel edge) moves by less
// than a pixel wherever a projector texel covers at most ~8 pixels, which holds
// for every scene below (the largest magnification is in the room: a 16-texel
// image over a 150-degree frustum, < 6 px per texel at 160 px).
#include <catch2/catch.hpp>

#include <cmath>

#include "extremes_support.hpp"

using namespace spanlight::xt;

namespace {

constexpr int tolerance = 3;

void check(sc::Scene s, int radius, int min_covered, int min_lit, const std::string& name, int tol = tolerance) {
  snap_positions_to_q16(s);
  const Both b = render_both(s);
  dump(b, name);
  const Agreement a = agree(b, radius, tol);
  int lit = 0;  // pixels the projector lights in the float model
  for (std::size_t i = 0; i < b.ref.object.size(); ++i)
    lit += b.ref.object[i] >= 0 && b.ref.light_rgb[i * 3] > static_cast<float>(s.ambient.x) + 0.01f;
  INFO(name << ": " << describe(a, s.width) << "; lit by the projector (float) " << lit);
  CHECK(a.covered_ref >= min_covered);
  CHECK(lit >= min_lit);
  CHECK(a.unexplained == 0);
}

// A camera high above a floor looks down at a projector standing on it.
sc::Scene floor_with_projector(double fovy, bool one_triangle) {
  sc::Scene s = make_scene(128, 128, {0, 14, 0.01}, {0, 0, 0}, {0, 0, -1}, 70.0, 1.0, 40.0);
  s.ambient = glm::dvec3(0.15);
  s.textures.push_back(texture("slide", checker_image(16, 16, 4, {255, 240, 200}, {90, 160, 255}), sc::Filter::nearest,
                               sc::Wrap::clamp));
  if (one_triangle) {
    // One triangle around everything: q = 0 (the projector's eye plane z = 0)
    // crosses its interior, and so do all four frustum sides.
    s.objects.push_back(triangle("floor", {glm::dvec3(-30, 0, 20), glm::dvec3(30, 0, 20), glm::dvec3(0, 0, -40)}));
  } else {
    s.objects.push_back(quad("floor", {glm::dvec3(-10, 0, 10), glm::dvec3(10, 0, 10), glm::dvec3(10, 0, -10), glm::dvec3(-10, 0, -10)}));
  }
  // Just above the floor, looking along -z and slightly down: the floor
  // behind it (z > 0) has q < 0 and must stay dark (no back-projection).
  s.projectors.push_back(projector({0.5, 0.75, 0}, {0.5, 0.25, -4}, {0, 1, 0}, fovy, 0.25, 30.0, 0, glm::dvec3(0.8)));
  return s;
}

}  // namespace

TEST_CASE("geometry behind the projector (q < 0) gets no light", "[extremes][projector]") {
  for (const double fovy : {60.0, 120.0, 170.0}) {
    check(floor_with_projector(fovy, false), 1, 8000, 500, "behind_" + std::to_string(static_cast<int>(fovy)));
  }
  // A direct check of condition 1 on the fixed picture: on the floor behind the
  // projector's eye plane (z > 0.25 there, away from the plane), only ambient.
  sc::Scene s = floor_with_projector(120.0, false);
  snap_positions_to_q16(s);
  const Both b = render_both(s);
  const glm::dmat4 inverse = glm::inverse(sc::camera_view_projection(s));
  int behind = 0, lit_behind = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      // Where this pixel's ray meets the floor y = 0.
      const glm::dvec4 a = inverse * glm::dvec4((x + 0.5) / s.width * 2 - 1, 1 - (y + 0.5) / s.height * 2, -1, 1);
      const glm::dvec4 c = inverse * glm::dvec4((x + 0.5) / s.width * 2 - 1, 1 - (y + 0.5) / s.height * 2, 1, 1);
      const glm::dvec3 p0 = glm::dvec3(a) / a.w, p1 = glm::dvec3(c) / c.w;
      const glm::dvec3 hit = p0 + (p1 - p0) * (p0.y / (p0.y - p1.y));
      if (std::fabs(hit.x) > 9.5 || hit.z < 0.25 || hit.z > 9.5) continue;
      ++behind;
      const auto i = static_cast<std::size_t>(y * s.width + x) * 3;
      lit_behind += b.fixed.rgb[i] > fm::to_byte(0.15) + 1;
    }
  INFO(behind << " floor pixels behind the projector, " << lit_behind << " of them lit");
  CHECK(behind > 2000);
  CHECK(lit_behind == 0);
}

TEST_CASE("q changing sign inside one triangle: light stops at the projector's eye plane", "[extremes][projector]") {
  for (const double fovy : {90.0, 150.0}) {
    check(floor_with_projector(fovy, true), 1, 8000, 500, "q_sign_" + std::to_string(static_cast<int>(fovy)));
  }
}

TEST_CASE("surfaces on and beside the projector's near and far planes", "[extremes][projector]") {
  // Walls facing the projector at distances near * (1 -+ 2^-8) and far * (1 -+ 2^-8):
  // outside and inside condition 3 by ~1e-3 of window depth at the near plane
  // and by 2^-8 * near / far ... of r/q at the far plane (still > 2^10 steps of
  // the Q3.28 r/q). The walls exactly on a plane have r/q = 0 or 1 exactly in
  // real arithmetic: either renderer may round them to either side, so those
  // two are only required to render without crashing and to agree elsewhere.
  const double pn = 2.0, pf = 16.0;
  for (const bool exactly_on : {false, true}) {
    sc::Scene s = make_scene(160, 120, {0, 5, 5}, {0, 1, -8}, {0, 1, 0}, 50.0, 0.5, 60.0);
    s.ambient = glm::dvec3(0.2);
    s.textures.push_back(texture("white", solid_image(2, 2, {255, 255, 255}), sc::Filter::nearest, sc::Wrap::clamp));
    s.projectors.push_back(projector({0, 1, 0}, {0, 1, -1}, {0, 1, 0}, 100.0, pn, pf, 0, glm::dvec3(0.7)));
    const double e = std::ldexp(1.0, -8);
    const double at[4] = {pn * (1 - e), pn * (1 + e), pf * (1 - e), pf * (1 + e)};
    for (int k = 0; k < 4; ++k) {
      const double d = exactly_on ? (k < 2 ? pn : pf) : at[k];
      const double side = k % 2 == 0 ? -1.0 : 1.0;
      // Near walls: 0.8 x 1 at x = -+0.6; far walls: 6 x 4 at x = -+4.
      const double cx = side * (k < 2 ? 0.6 : 4.0), hw = k < 2 ? 0.4 : 3.0, y0 = 0.5, y1 = k < 2 ? 1.5 : 4.5;
      s.objects.push_back(quad("wall" + std::to_string(k), {glm::dvec3(cx - hw, y0, -d), glm::dvec3(cx + hw, y0, -d),
                                                            glm::dvec3(cx + hw, y1, -d), glm::dvec3(cx - hw, y1, -d)},
                               glm::dvec3(0.9, 0.9, 0.6)));
    }
    snap_positions_to_q16(s);
    const Both b = render_both(s);
    dump(b, exactly_on ? "proj_planes_on" : "proj_planes_beside");
    const Agreement a = agree(b, 1, tolerance);
    // Lit pixels of each wall in both renderers; every wall pixel shows one
    // of the two colours (ambient only, or ambient + projector).
    int lit_fixed[4] = {}, lit_ref[4] = {}, covered[4] = {}, neither = 0;
    const int unlit_level = fm::to_byte(0.2 * 0.9), lit_level = fm::to_byte(0.9 * 0.9);
    for (std::size_t i = 0; i < b.ref.object.size(); ++i) {
      const int o = b.ref.object[i];
      if (o < 0) continue;
      ++covered[o];
      lit_ref[o] += b.ref.rgb[i * 3] > unlit_level + tolerance;
      lit_fixed[o] += b.fixed.rgb[i * 3] > unlit_level + tolerance;
      const int r = b.fixed.rgb[i * 3];
      neither += std::abs(r - unlit_level) > tolerance && std::abs(r - lit_level) > tolerance && b.fixed.depth[i] != b.depth_clear;
    }
    INFO((exactly_on ? "exactly on the planes: " : "beside the planes: ") << describe(a, s.width));
    INFO("walls: " << covered[0] << ", " << covered[1] << ", " << covered[2] << ", " << covered[3] << " px; lit float "
                   << lit_ref[0] << ", " << lit_ref[1] << ", " << lit_ref[2] << ", " << lit_ref[3] << "; lit fixed "
                   << lit_fixed[0] << ", " << lit_fixed[1] << ", " << lit_fixed[2] << ", " << lit_fixed[3]);
    for (int k = 0; k < 4; ++k) CHECK(covered[k] > 100);
    CHECK(neither == 0);
    if (!exactly_on) {
      CHECK(a.unexplained == 0);
      CHECK(lit_ref[0] == 0);  // before the near plane
      CHECK(lit_fixed[0] == 0);
      CHECK(lit_ref[1] == covered[1]);  // just past it
      CHECK(lit_fixed[1] == covered[1]);
      CHECK(lit_ref[2] == covered[2]);  // just before the far plane
      CHECK(lit_fixed[2] == covered[2]);
      CHECK(lit_ref[3] == 0);  // beyond it
      CHECK(lit_fixed[3] == 0);
    }
  }
}

// The slide is a bilinear checker of 2-texel cells: neighbouring texels differ
// by up to 195 levels, so an error of e texels in s/q, t/q changes a pixel by
// up to 195 e levels. e <= 2^-3 (span drift) + 2^-8 (8-bit bilinear weights)
// gives 195 * 0.129 = 25.2 levels, plus the 3 levels of colour rounding: 29.
// Near a 170-degree frustum's sides one texel covers tens of pixels, so that
// error is what a pixel can show there; beyond it only at light boundaries.
constexpr int bilinear_tolerance = 29;

TEST_CASE("a projector inside a room with a 100 to 170 degree field of view", "[extremes][projector]") {
  for (const double fovy : {100.0, 150.0, 170.0}) {
    for (const double aspect : {1.0, 2.5}) {
      sc::Scene s = make_scene(160, 120, {-3.5, 2.5, 3.5}, {1, 0.5, -1}, {0, 1, 0}, 90.0, 0.05, 30.0);
      s.ambient = glm::dvec3(0.1);
      s.textures.push_back(texture("slide", checker_image(16, 16, 2, {255, 220, 180}, {60, 120, 255}), sc::Filter::bilinear,
                                   sc::Wrap::clamp));
      for (sc::Object& face : room({-4, 0, -4}, {4, 3, 4})) s.objects.push_back(std::move(face));
      sc::Projector p = projector({0.25, 1.5, -0.5}, {1.0, 1.25, -2.0}, {0, 1, 0}, fovy, 0.1, 20.0, 0, glm::dvec3(0.9));
      p.aspect = aspect;
      s.projectors.push_back(p);
      INFO("fovy " << fovy << ", aspect " << aspect);
      check(s, 1, 15000, 1000, "room_" + std::to_string(static_cast<int>(fovy)) + "_" + std::to_string(aspect),
            bilinear_tolerance);
    }
  }
}
