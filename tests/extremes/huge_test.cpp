// Huge: a floor 10 km across seen from 1 m (far / near = 2e5), coordinates up
// to 1e4 units, texture coordinates repeating 1e4 times, and what happens at
// and beyond the input formats' limits (prepare.cpp: |coord| < 16384,
// matrix entries below 2^13).
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>

#include "extremes_support.hpp"

using namespace spanlight::xt;

namespace {

constexpr int tolerance = 3;

sc::Scene ten_km_floor(int width, int height, bool textured) {
  // Eye 1 m above the floor, looking slightly down toward the horizon.
  sc::Scene s = make_scene(width, height, {0, 1, 0}, {0, 0.75, -10}, {0, 1, 0}, 70.0, 0.05, 10000.0);
  s.ambient = glm::dvec3(0.3);
  s.textures.push_back(texture("white", solid_image(1, 1, {255, 255, 255}), sc::Filter::nearest, sc::Wrap::clamp));
  s.textures.push_back(texture("tiles", checker_image(4, 4, 2, {230, 230, 230}, {60, 60, 60}), sc::Filter::bilinear, sc::Wrap::repeat));
  // Two triangles 10 km on a side; uv repeats once per metre (1e4 times across).
  sc::Object floor = quad("floor", {glm::dvec3(-5000, 0, 5000), glm::dvec3(5000, 0, 5000), glm::dvec3(5000, 0, -5000),
                                    glm::dvec3(-5000, 0, -5000)},
                          glm::dvec3(0.8, 0.85, 0.7), {glm::dvec2(0, 0), glm::dvec2(1e4, 0), glm::dvec2(1e4, 1e4), glm::dvec2(0, 1e4)});
  if (textured) floor.texture = 1;
  s.objects.push_back(floor);
  // A tower 1 km away and a wall 4 km away, in front of the horizon.
  s.objects.push_back(quad("tower", {glm::dvec3(-60, 0, -1000), glm::dvec3(-20, 0, -1000), glm::dvec3(-20, 300, -1000),
                                     glm::dvec3(-60, 300, -1000)}, glm::dvec3(0.9, 0.4, 0.3)));
  s.objects.push_back(quad("wall", {glm::dvec3(200, 0, -4000), glm::dvec3(1500, 0, -4000), glm::dvec3(1500, 150, -4000),
                                    glm::dvec3(200, 150, -4000)}, glm::dvec3(0.3, 0.5, 0.9)));
  // A spotlight 10 m up, 30 m ahead, pointing down the road.
  s.projectors.push_back(projector({0, 10, -30}, {0, 0, -80}, {0, 1, 0}, 50.0, 1.0, 500.0, 0, glm::dvec3(0.6)));
  return s;
}

}  // namespace

TEST_CASE("a 10 km floor seen from 1 m with far/near = 2e5 agrees with the float model", "[extremes][huge]") {
  // Flat colours: every difference must be an edge (silhouette, horizon,
  // light boundary) moved by less than a pixel. The floor crosses the near
  // plane behind the eye and reaches ~10^5 px beyond the viewport, so this
  // runs the near clip and the guard band clip on every triangle.
  sc::Scene s = ten_km_floor(240, 160, false);
  snap_positions_to_q16(s);
  const Both b = render_both(s);
  dump(b, "ten_km");
  const Agreement a = agree(b, 1, tolerance);
  INFO(describe(a, s.width));
  CHECK(a.covered_ref > 15000);
  CHECK(a.unexplained == 0);
  CHECK(a.stats.pct_over_8_lsb < 0.5);
}

TEST_CASE("texture coordinates repeating 1e4 times across one triangle", "[extremes][huge]") {
  // uv runs to 1e4 repeats of a 4-texel checker: texel coordinates up to 4e4,
  // 16 integer bits, so prepare keeps uv_frac_bits = 29 - 16 = 13 sub-texel
  // bits. Near the eye (texels larger than a pixel) bilinear filtering gives a
  // smooth picture that must agree: the uv error is <= 2^-3 texel (span drift)
  // + 2^-8 (bilinear weight) + 2^-13, and neighbouring texels differ by 170
  // levels, so <= 170 * 0.1289 = 21.9 + 3 levels of rounding: 25 levels.
  // Toward the horizon one pixel covers many texels; without mipmaps both
  // renderers alias there and a 1/8-texel difference picks other texels, so
  // only the mean level of that region is compared (within 2 levels: the
  // checker averages to the same grey in both).
  sc::Scene s = ten_km_floor(240, 160, true);
  snap_positions_to_q16(s);
  const auto prepared = pr::prepare_scene(s);
  CHECK(prepared->objects[0].uv_frac_bits == 13);
  const Both b = render_both(s);
  dump(b, "ten_km_textured");

  // Split the floor's pixels by distance: the eye ray meets y = 0 at distance
  // 1 / sin(angle below the horizon); a texel (1/4 m) covers > 2 px while
  // distance < sqrt(focal / 8) (vertical footprint ~ distance^2 / focal).
  const glm::dmat4 inverse = glm::inverse(sc::camera_view_projection(s));
  const double focal = (s.height / 2.0) / std::tan(glm::radians(s.camera.fovy_deg / 2.0));
  const double near_field = std::sqrt(focal / 8.0);
  int near_pixels = 0, near_bad = 0, far_pixels = 0;
  double far_sum_fixed = 0, far_sum_ref = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const auto i = static_cast<std::size_t>(y * s.width + x);
      if (b.ref.object[i] != 0 || b.fixed.depth[i] == b.depth_clear) continue;
      const glm::dvec4 p0 = inverse * glm::dvec4((x + 0.5) / s.width * 2 - 1, 1 - (y + 0.5) / s.height * 2, -1, 1);
      const glm::dvec4 p1 = inverse * glm::dvec4((x + 0.5) / s.width * 2 - 1, 1 - (y + 0.5) / s.height * 2, 1, 1);
      const glm::dvec3 a = glm::dvec3(p0) / p0.w, c = glm::dvec3(p1) / p1.w;
      const double t = a.y / (a.y - c.y);
      const double distance = glm::length((c - a) * t + a - s.camera.eye);
      if (distance < near_field) {
        ++near_pixels;
        near_bad += channel_diff(b.fixed.rgb, b.ref.rgb, i, i) > 25;
      } else if (distance > 20.0) {
        ++far_pixels;
        far_sum_fixed += b.fixed.rgb[i * 3 + 1];
        far_sum_ref += b.ref.rgb[i * 3 + 1];
      }
    }
  INFO(describe(agree(b, 1, tolerance), s.width));
  INFO("near field (< " << near_field << " m): " << near_pixels << " px, " << near_bad << " over 25 levels; far field: "
                        << far_pixels << " px, mean green fixed " << far_sum_fixed / far_pixels << ", float "
                        << far_sum_ref / far_pixels);
  CHECK(near_pixels > 1000);
  CHECK(near_bad == 0);
  CHECK(far_pixels > 500);
  CHECK(std::fabs(far_sum_fixed - far_sum_ref) / far_pixels < 2.0);
}

TEST_CASE("coordinates up to 1e4 units: a room 2e4 units across around the eye", "[extremes][huge]") {
  sc::Scene s = make_scene(200, 150, {0, 2, 0}, {1, 1.5, -3}, {0, 1, 0}, 80.0, 0.1, 30000.0);
  s.ambient = glm::dvec3(0.25);
  s.textures.push_back(texture("slide", checker_image(8, 8, 2, {255, 230, 200}, {100, 140, 255}), sc::Filter::nearest,
                               sc::Wrap::clamp));
  for (sc::Object& face : room({-9999, 0, -9999}, {9999, 5000, 9999})) s.objects.push_back(std::move(face));
  // Pillars at the room's far corners and one close by.
  s.objects.push_back(quad("pillar", {glm::dvec3(9000, 0, -9000), glm::dvec3(9500, 0, -9500), glm::dvec3(9500, 4000, -9500),
                                      glm::dvec3(9000, 4000, -9000)}, glm::dvec3(0.9, 0.9, 0.2)));
  s.objects.push_back(quad("post", {glm::dvec3(2, 0, -6), glm::dvec3(2.5, 0, -6), glm::dvec3(2.5, 3, -6), glm::dvec3(2, 3, -6)},
                           glm::dvec3(0.2, 0.9, 0.2)));
  s.projectors.push_back(projector({0, 3000, 0}, {4000, 0, -6000}, {0, 1, 0}, 60.0, 10.0, 20000.0, 0, glm::dvec3(0.7)));
  snap_positions_to_q16(s);
  const Both b = render_both(s);
  dump(b, "room_1e4");
  const Agreement a = agree(b, 1, tolerance);
  INFO(describe(a, s.width));
  CHECK(a.covered_ref == s.width * s.height);
  CHECK(a.unexplained == 0);
}

TEST_CASE("uv offset by many repeats: sub-texel bits shrink as documented", "[extremes][huge]") {
  // A face-on square showing one repeat of a checker, magnified (one texel
  // over many pixels), at uv [0, 1] and offset by many repeats. With repeat
  // and a power-of-two size both show the same texels; the larger texel
  // coordinates leave fewer sub-texel bits (prepare.cpp, uv_frac_bits_for:
  // 29 minus the integer bits of the largest |uv * size|, from 8 to 16), so the
  // bilinear blend is quantised to 2^-frac texel: a 16-texel image at 1e4
  // repeats has 1.6e5 texels -> 18 bits -> 11 sub-texel bits; 4096 texels
  // at 500 repeats (the most below prepare's 2^21 texels) -> 2.05e6 -> 21 bits -> 8.
  // Bound: neighbouring texels differ by G = 200 levels; the sampled position
  // is off by <= 2^-frac (quantised uv) + 2^-8 (bilinear weight) + 2^-(T+1)
  // (span drift on a face-on square, where the quadratic steps are exact up to
  // their rounding, which segments.hpp keeps below 2^-(T+1) texel, T the
  // tolerance knob); the colour by G times that per axis, plus 3.
  const int tolerance_log2 = spanlight::Knobs{}.tolerance_log2;
  for (const int size : {16, 4096}) {
    if (sanitized && size == 4096) continue;  // 48 MB texture; the plain build covers it
    for (const double offset : {0.0, size == 16 ? 1e4 : 500.0}) {
      sc::Scene s = make_scene(128, 128, {0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 30.0, 1.0, 10.0);
      s.ambient = glm::dvec3(1.0);
      const int cell = size / 4;
      s.textures.push_back(texture("checker", checker_image(size, size, cell, {240, 240, 240}, {40, 40, 40}),
                                   sc::Filter::bilinear, sc::Wrap::repeat));
      // One checker cell boundary crosses the middle; the square shows 1/8 of the image.
      const double u0 = offset + 0.25 - 1.0 / 16, u1 = offset + 0.25 + 1.0 / 16;
      sc::Object square = quad("square", {glm::dvec3(-1, -1, 0), glm::dvec3(1, -1, 0), glm::dvec3(1, 1, 0), glm::dvec3(-1, 1, 0)},
                               glm::dvec3(1.0), {glm::dvec2(u0, u0), glm::dvec2(u1, u0), glm::dvec2(u1, u1), glm::dvec2(u0, u1)});
      square.texture = 0;
      s.objects.push_back(square);
      const auto prepared = pr::prepare_scene(s);
      const int frac = prepared->objects[0].uv_frac_bits;
      const double largest = (offset + 0.3125) * size;
      const int expected_frac = largest < 1.0 ? 16 : std::clamp(29 - (static_cast<int>(std::floor(std::log2(largest))) + 1), 8, 16);
      CHECK(frac == expected_frac);
      CHECK(frac == (offset == 0.0 ? (size == 16 ? 16 : 16) : (size == 16 ? 11 : 8)));
      const double error_texels = std::ldexp(1.0, -frac) + std::ldexp(1.0, -8) + std::ldexp(1.0, -(tolerance_log2 + 1));
      const int bound = static_cast<int>(std::ceil(200.0 * 2.0 * error_texels)) + tolerance;
      const Both b = render_both(s);
      const Agreement a = agree(b, 0, bound);
      INFO("texture " << size << ", uv offset " << offset << ": uv_frac_bits " << frac << ", bound " << bound << " levels; "
                      << describe(a, s.width));
      CHECK(a.over_tolerance == 0);
    }
  }
}

TEST_CASE("beyond the formats: coordinates >= 16384 and matrix entries >= 2^13 are refused by prepare", "[extremes][huge]") {
  auto scene_with = [](double coordinate, double scale) {
    sc::Scene s = make_scene(32, 32, {0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60.0, 0.1, 100.0);
    sc::Object t = triangle("t", {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, coordinate, 0)});
    t.model = glm::dmat4(scale);
    t.model[3][3] = 1.0;
    s.objects.push_back(t);
    return s;
  };
  // Positions: |coord| < 16384 (prepare.cpp, position_limit; Q15.16 with a bit to spare).
  CHECK_NOTHROW(pr::prepare_scene(scene_with(16383.99, 1.0)));
  CHECK_THROWS_AS(pr::prepare_scene(scene_with(16384.0, 1.0)), pr::PrepareError);
  CHECK_THROWS_AS(pr::prepare_scene(scene_with(-1e9, 1.0)), pr::PrepareError);
  // Matrices: P * V * M is kept with >= 16 fraction bits (prepare.cpp, to_mat4_block), so
  // every entry of the product must be below 2^29 / 2^16 = 2^13 (less half a step).
  const double ok = 8191.0, too_big = 8192.0;
  auto with_matrix_entry = [](double entry) {
    // far / near = 1e6: P's depth row scales z_eye by (f + n) / (f - n) = 1 + 2e-6 only.
    sc::Scene s = make_scene(32, 32, {0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60.0, 1.0, 1e6);
    sc::Object t = triangle("t", {glm::dvec3(0, 0, 0), glm::dvec3(1e-3, 0, 0), glm::dvec3(0, 1e-3, 0)});
    // The camera looks down -z from z = 5 with lookAt = a translation; P's
    // entries are < 2: put the large entry where P * V leaves it alone (w row).
    t.model = glm::dmat4(1.0);
    t.model[0][2] = -entry;  // z_eye gets -entry * x: clip w = entry * x
    s.objects.push_back(t);
    return s;
  };
  const auto accepted = pr::prepare_scene(with_matrix_entry(ok));
  const auto& m = accepted->clip_from_object[0];
  double largest = 0;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) largest = std::max(largest, std::fabs(fixedpoint::mat4_block_entry(m, c, r)));
  INFO("largest clip-matrix entry accepted: " << largest << ", frac_bits " << m.frac_bits);
  CHECK(m.frac_bits == 16);
  CHECK(largest > 4096.0);
  CHECK_THROWS_AS(pr::prepare_scene(with_matrix_entry(too_big)), pr::PrepareError);
  // A camera whose projection alone is too large: fovy 0.02 degrees gives
  // cot(fovy / 2) = 5730 (accepted), 0.01 degrees 11459 (refused).
  sc::Scene narrow = scene_with(1.0, 1.0);
  narrow.camera.fovy_deg = 0.02;
  CHECK_NOTHROW(pr::prepare_scene(narrow));
  narrow.camera.fovy_deg = 0.01;
  CHECK_THROWS_AS(pr::prepare_scene(narrow), pr::PrepareError);
}

TEST_CASE("clip-space w near the transform's bound: guard-band distances do not overflow", "[extremes][huge]") {
  // Regression (found by this suite, fixed; docs/limits.md): clip.hpp's plane_distance computes guard * c.w + c.x in
  // int64. Prepare accepts clip-matrix entries < 2^13 and positions < 2^14,
  // so |w| can reach 3 * 2^13 * 2^14 + 2^13 units ~ 4.0e8 units = 1.73e18 raw
  // (Q31.32); with the guard band G = 6 (viewports up to 2285 px) G * w
  // overflows int64 (9.22e18) once w > 3.58e8 units: signed overflow (UB; the
  // _asan twin stops on it) and, wrapped, a visible triangle is clipped away.
  // A valid scene reaches it: a model matrix with entries 8000 and a far
  // plane beyond 3.6e8. The float model draws the triangle.
  // The fix: the guard planes' distance on quarter values,
  // guard * (c.w >> 2) +- (c.x >> 2) (< 7 * 2^59 for |c| < 2^61; the lost two
  // bits are 2^-30 units, and crossing() only uses the ratio).
  sc::Scene s = make_scene(64, 64, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90.0, 1.0, 1e9);
  s.ambient = glm::dvec3(0.6);
  // Vertex 0 has w = 8000 * 48000 = 3.84e8 units; the others are much nearer.
  sc::Object t = triangle("far_away", {glm::dvec3(16000, 16000, 16000), glm::dvec3(0, 0, 1000), glm::dvec3(1000, 0, 1000)});
  t.model = glm::dmat4(0.0);
  t.model[0][0] = 8000;  // x_eye = 8000 x
  t.model[1][1] = 8000;  // y_eye = 8000 y
  t.model[0][2] = t.model[1][2] = t.model[2][2] = -8000;  // z_eye = -8000 (x + y + z)
  t.model[3][3] = 1;
  s.objects.push_back(t);
  const auto prepared = pr::prepare_scene(s);  // accepted: every entry of P * V * M is < 2^13
  const spanlight::Vec4Wide far_vertex = spanlight::transform(prepared->clip_from_object[0],
                                                              prepared->objects[0].positions);
  const std::int64_t guard = spanlight::guard_band(s.width, s.height);
  std::int64_t product = 0;
  const bool overflows = __builtin_mul_overflow(guard, far_vertex.w, &product);
  INFO("w of vertex 0: " << static_cast<double>(far_vertex.w) * 0x1p-32 << " units, guard band " << guard
                         << (overflows ? ": G * w overflows int64" : ""));
  CHECK(overflows);  // the case reaches the bound it is about
  const Both b = render_both(s);
  const Agreement a = agree(b, 1, tolerance);
  INFO(describe(a, s.width));
  CHECK(a.covered_ref > 60);
  CHECK(a.unexplained == 0);
}

TEST_CASE("texel coordinates beyond 2^21 are refused by prepare, not wrapped", "[extremes][huge]") {
  // Regression (found by this suite, fixed; docs/limits.md): prepare.cpp's uv_frac_bits_for keeps |uv * size| * 2^frac
  // below 2^30 only down to frac = 0; a larger texel coordinate (allowed by
  // the loader: any finite uv) is still rounded with llround and cast to
  // int32, which wraps above 2^31, and 2_triangle/attributes.hpp's `v[1]->u - a.u0`
  // (int32) and mix3's deltas assume |u| < 2^29 (3_span/exact.hpp). Positions
  // have the analogous check (PrepareError beyond 16384 units); uvs have none.
  // The fix: in prepare_scene, throw PrepareError when the largest
  // |uv * size| of an object is not below 2^29 (before uv_frac_bits_for).
  // The bound is now 2^21 texels (prepare.hpp, texel_coordinate_limit: 8 sub-texel bits in 29).
  // uv = 2e5 on a 4096-texel texture is 8.2e8 texels (> 2^29 = 5.4e8).
  sc::Scene s = make_scene(64, 64, {0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 40.0, 1.0, 10.0);
  s.ambient = glm::dvec3(1.0);
  s.textures.push_back(texture("big", checker_image(4096, 1, 1024), sc::Filter::nearest, sc::Wrap::repeat));
  sc::Object square = quad("square", {glm::dvec3(-1, -1, 0), glm::dvec3(1, -1, 0), glm::dvec3(1, 1, 0), glm::dvec3(-1, 1, 0)},
                           glm::dvec3(1.0), {glm::dvec2(-2e5, 0), glm::dvec2(2e5, 0), glm::dvec2(2e5, 0.5), glm::dvec2(-2e5, 0.5)});
  square.texture = 0;
  s.objects.push_back(square);
  CHECK_THROWS_AS(pr::prepare_scene(s), pr::PrepareError);
  // Just beyond the bound (uv 512.5: 2.0992e6 texels > 2^21 = 2.0972e6) it is refused,
  // just inside it (uv 511.5: 2.0951e6 texels) accepted, with 8 sub-texel bits.
  REQUIRE(pr::texel_coordinate_limit == 2097152.0);
  for (auto& uv : s.objects[0].mesh.uvs) uv.x = uv.x > 0 ? 512.5 : -512.5;
  CHECK_THROWS_AS(pr::prepare_scene(s), pr::PrepareError);
  for (auto& uv : s.objects[0].mesh.uvs) uv.x = uv.x > 0 ? 511.5 : -511.5;
  std::unique_ptr<pr::PreparedStorage> inside;
  CHECK_NOTHROW(inside = pr::prepare_scene(s));
  if (inside) CHECK(inside->objects[0].uv_frac_bits == 8);
}

TEST_CASE("clipping never keeps a vertex beyond a plane it clipped against", "[extremes][huge]") {
  // Regression (found by tests/fuzz/fuzz_raster, fixed; docs/limits.md): clip.hpp's crossing()
  // shifts both distances down until the divisor fits 32 bits, truncating
  // both; with |da| ~ 2^61 and |db| < 2^29 the two shifted values are equal
  // and t comes out as exactly 1: the "cut" vertex is the outside vertex
  // itself. Here the outside vertex is behind the eye (w < 0), the clipped
  // polygon keeps it, and project() then divides by a clamped w = 1 and
  // overflows int64 (UBSan: project.hpp, `x_ratio * (width << 7)`). All
  // values are within the transform's bound (|c| < 4.0e8 units).
  // The fix: round the shifted divisor up, den = ((den - 1) >> excess) + 1,
  // so that t never passes the plane (then only lerp's floor can leave a cut
  // vertex outside, by at most G + 1 raw units of 2^-32).
  spanlight::ClipPolygon<1> poly{};
  poly.count = 3;
  poly.v[0].clip = {-1729417438739581032, 255326587679259949, 606915762305427753, 1127614113399725011};
  poly.v[1].clip = {-25431041, -50332672, -50332672, -50332672};
  poly.v[2].clip = {-1729417441282359296, -1729417441282359296, -1729417441282359296, -1729417441282359296};
  const std::int64_t guard = spanlight::guard_band(3936, 1);
  REQUIRE(guard == 3);
  REQUIRE(spanlight::clip_polygon(poly, guard, 0, 0));
  for (int k = 0; k < poly.count; ++k) {
    const spanlight::Vec4Wide& c = poly.v[k].clip;
    INFO("vertex " << k << ": x " << c.x << " y " << c.y << " z " << c.z << " w " << c.w);
    CHECK(c.w > 0);
    CHECK(c.z + c.w >= -8);  // near, to within lerp's rounding
    // Inside the guard band, to within rounding (on quarter values, which cannot overflow).
    CHECK(guard * (c.w >> 2) - std::max(std::abs(c.x >> 2), std::abs(c.y >> 2)) >= -8);
  }
}
