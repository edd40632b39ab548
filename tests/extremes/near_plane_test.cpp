// The eye's near plane: triangles that cross it and reach behind the eye,
// vertices with w near 0 (tiny near planes, vertices at the eye), vertices
// exactly on the near plane.
//
// Expectation, for every case: no crash, no UB (the _asan twin), and no
// unexplained pixel (extremes_support.hpp): the fixed picture differs from the
// float model's by more than `tolerance` levels only within `radius` pixels of
// an edge of the reference picture. Why those bounds hold near the near plane:
// the clip stage cuts an edge at a parameter t rounded to 2^-30 (clip.hpp,
// crossing), which slides the new vertex ALONG the edge's line; that leaves
// the triangle's side edges where they are and moves only the cut edge on the
// near plane, by |dx/dt| * 2^-30. The cut vertex lies on the plane w = near,
// so |d(x/w)/dt| <= (|dx| + G |dw|) / near (G the guard band, <= 6), which for
// the scenes below (clip-space edge deltas < 200 units, near >= 1e-3) is
// < 1.4e6 * 2^-30 ~ 1.3e-3 NDC, under 0.2 px at 320 px: a one-pixel
// neighbourhood covers it. Colours are flat or bilinear-filtered checkers; a
// flat colour is exact up to the 8-bit rounding steps of shade.hpp (ambient,
// light, modulate: <= 2 levels).
// Positions are put on the Q15.16 grid first (snap_positions_to_q16), so both
// renderers draw the same geometry: unsnapped, a plane crossing a 1e-3 near
// plane at slope 0.02 has its cut moved 37 px by the 2^-17-unit rounding of
// its z alone (docs/limits.md, "What the formats cost").
#include <catch2/catch.hpp>

#include <cmath>

#include "extremes_support.hpp"

using namespace spanlight::xt;

namespace {

constexpr int tolerance = 3;  // levels: the <= 2-level rounding of shade.hpp's three 8-bit steps, plus one

// A corridor around the eye: a textured floor and two walls that extend
// 20 units behind the eye and 40 in front; a projector lights part of it.
// `scale` shrinks the whole scene (and the camera's far plane with it).
sc::Scene corridor(double near, double scale = 1.0) {
  const double k = scale;
  sc::Scene s = make_scene(160, 120, {0, 1.5 * k, 0}, {0.2 * k, 1.3 * k, -k}, {0, 1, 0}, 70.0, near, 100.0 * k);
  s.ambient = glm::dvec3(0.25);
  s.textures.push_back(texture("checker", checker_image(8, 8, 4), sc::Filter::bilinear, sc::Wrap::repeat));
  s.textures.push_back(texture("white", solid_image(1, 1, {255, 255, 255}), sc::Filter::nearest, sc::Wrap::clamp));
  sc::Object floor = quad("floor", {k * glm::dvec3(-3, 0, 20), k * glm::dvec3(3, 0, 20), k * glm::dvec3(3, 0, -40),
                                    k * glm::dvec3(-3, 0, -40)},
                          glm::dvec3(1.0), {glm::dvec2(0, 0), glm::dvec2(3, 0), glm::dvec2(3, 30), glm::dvec2(0, 30)});
  floor.texture = 0;
  s.objects.push_back(floor);
  s.objects.push_back(quad("left", {k * glm::dvec3(-3, 0, -40), k * glm::dvec3(-3, 3, -40), k * glm::dvec3(-3, 3, 20),
                                    k * glm::dvec3(-3, 0, 20)}, glm::dvec3(0.8, 0.6, 0.5)));
  s.objects.push_back(quad("right", {k * glm::dvec3(0.75, 0, 20), k * glm::dvec3(0.75, 3, 20), k * glm::dvec3(0.75, 3, -40),
                                     k * glm::dvec3(0.75, 0, -40)}, glm::dvec3(0.5, 0.7, 0.9)));
  s.projectors.push_back(projector(k * glm::dvec3(-1, 2.5, 2), k * glm::dvec3(0, 0.5, -6), {0, 1, 0}, 40.0, 0.5 * k,
                                   60.0 * k, 1, glm::dvec3(0.6)));
  return s;
}

// A plane z = -near + slope * x through the near plane's line x = 0: its
// left half is in front of the near plane, its right half behind it, so the
// near-plane cut is a vertical edge in the middle of the picture. A wide
// projector with a white image lights a window of it.
sc::Scene cut_in_view(double near, double slope) {
  sc::Scene s = make_scene(160, 120, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0, near, 100.0);
  s.ambient = glm::dvec3(0.3);
  s.textures.push_back(texture("white", solid_image(1, 1, {255, 255, 255}), sc::Filter::nearest, sc::Wrap::clamp));
  s.objects.push_back(quad("wall", {glm::dvec3(-50, -50, -near - slope * 50), glm::dvec3(50, -50, -near + slope * 50),
                                    glm::dvec3(50, 50, -near + slope * 50), glm::dvec3(-50, 50, -near - slope * 50)},
                           glm::dvec3(0.9, 0.8, 0.6)));
  s.projectors.push_back(projector({-0.3, 0.2, 0.5}, {-0.3, 0.2, -1}, {0, 1, 0}, 30.0, 0.1, 200.0, 0, glm::dvec3(0.5)));
  return s;
}

void check_agreement(sc::Scene s, int radius, int min_covered, const std::string& name = "case") {
  snap_positions_to_q16(s);
  const Both b = render_both(s);
  dump(b, name);
  const Agreement a = agree(b, radius, tolerance);
  INFO(describe(a, s.width));
  CHECK(a.covered_ref >= min_covered);  // the case is not vacuous
  CHECK(a.unexplained == 0);
}

}  // namespace

TEST_CASE("triangles crossing the near plane and reaching behind the eye agree with the float model", "[extremes][near]") {
  for (const double near : {0.05, 1e-3}) {
    INFO("near " << near);
    check_agreement(corridor(near), 1, 15000, "corridor_" + std::to_string(near));
  }
}

TEST_CASE("a near-plane cut edge in the middle of the picture agrees with the float model", "[extremes][near]") {
  for (const double slope : {0.25, 1.0 / 64, 3.0}) {
    for (const double near : {1.0 / 8, 1.0 / 1024}) {
      INFO("near " << near << ", slope " << slope);
      check_agreement(cut_in_view(near, slope), 1, 4000, "cut_" + std::to_string(near) + "_" + std::to_string(slope));
    }
  }
}

TEST_CASE("vertices with w near 0: tiny near planes and vertices at or beside the eye", "[extremes][near]") {
  SECTION("near 1e-5 and 1e-7: the corridor still agrees away from edges") {
    // A cut vertex on a near plane of 1e-5 has w = 4.3e4 raw (Q31.32), of
    // 1e-7 only 430: few significant bits. The corridor's near-plane cuts lie
    // far outside the guard band, so the guard clip removes them; what stays
    // visible are the side edges, whose lines the cut vertices still lie on
    // to 2^-32 per component. Depth: a window depth within 2^-24 of 1 is
    // where 24-bit depth runs out (depth_test.cpp), so with near 1e-7 the
    // corridor is shrunk to fit in 1 unit (1 - z_w = near (f - z) / ((f - near) z)
    // stays above 2^-24 for z < near * 2^24 = 1.67).
    check_agreement(corridor(1e-5), 1, 15000, "corridor_1e-5");
    check_agreement(corridor(1e-7, 1.0 / 100), 1, 15000, "corridor_1e-7");
  }
  SECTION("triangles with a vertex exactly at the eye (w = 0), in the eye plane, and at w = 2^-16") {
    sc::Scene s = make_scene(96, 72, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0, 0.01, 50.0);
    s.ambient = glm::dvec3(0.5);
    s.objects.push_back(triangle("at_eye", {glm::dvec3(0, 0, 0), glm::dvec3(-2, -1, -5), glm::dvec3(2, -1.5, -5)}));
    s.objects.push_back(triangle("eye_plane", {glm::dvec3(3, 2, 0), glm::dvec3(-3, 2, -0.0), glm::dvec3(0, 1, -4)},
                                 glm::dvec3(0.2, 0.9, 0.4)));
    // The smallest w a Q15.16 position gives in front of the eye: z = -2^-16 (w = 2^16 raw).
    s.objects.push_back(triangle("w_2^-16", {glm::dvec3(0.5, -0.5, -std::ldexp(1.0, -16)), glm::dvec3(3, 1, -8), glm::dvec3(-1, 1, -8)},
                                 glm::dvec3(0.9, 0.3, 0.3)));
    check_agreement(s, 1, 800);
  }
}

TEST_CASE("vertices exactly on the near plane", "[extremes][near]") {
  // near = 0.5 and vertices at z = -0.5: window depth 0 exactly in double;
  // the fixed transform may round such a vertex one 2^-32 step to either side
  // of the plane, which clips a sliver of < 2^-32 units or nothing.
  sc::Scene s = make_scene(128, 96, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0, 0.5, 20.0);
  s.ambient = glm::dvec3(0.4);
  // A floor strip whose near edge lies on the near plane, and a triangle with
  // all three vertices on it (it lies in the plane: window depth 0).
  s.objects.push_back(quad("floor", {glm::dvec3(-0.2, -0.2, -0.5), glm::dvec3(0.2, -0.2, -0.5), glm::dvec3(2, -1, -10),
                                     glm::dvec3(-2, -1, -10)}, glm::dvec3(0.9, 0.8, 0.7)));
  s.objects.push_back(triangle("in_plane", {glm::dvec3(-0.1, 0.05, -0.5), glm::dvec3(0.1, 0.05, -0.5), glm::dvec3(0.0, 0.2, -0.5)},
                               glm::dvec3(0.3, 0.6, 0.9)));
  snap_positions_to_q16(s);
  const Both b = render_both(s);
  const Agreement a = agree(b, 1, tolerance);
  INFO(describe(a, s.width));
  CHECK(a.covered_ref > 1500);
  CHECK(a.unexplained == 0);
  // The in-plane triangle is drawn at depth 0 by both (nothing is nearer).
  int fixed_zero = 0, ref_zero = 0;
  for (std::size_t i = 0; i < b.ref.depth.size(); ++i) {
    fixed_zero += b.fixed.depth[i] == 0;
    ref_zero += b.ref.object[i] == 1;
  }
  INFO("in-plane triangle: float " << ref_zero << " pixels, fixed depth-0 pixels " << fixed_zero);
  CHECK(ref_zero > 300);
  CHECK(std::abs(fixed_zero - ref_zero) <= ref_zero / 20);
}
