// Shadow maps: a hand-made map checked texel by texel, and a small square
// occluder over a floor under a projector pointing straight down, where which
// pixels are shadowed follows from similar triangles.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "float_model/float_model.hpp"
#include "float_model/shadow_map.hpp"
#include "test_scenes.hpp"

namespace fm = spanlight::float_model;
namespace scene = spanlight::scene;

TEST_CASE("shadow lookups: nearest texel, pcf2x2 weights, rows from the bottom, clamped indices", "[shadow]") {
  // 4 x 4 map, top row first. Columns 0-1 are occluded at depth 0.3, columns 2-3
  // clear (1.0), except the top-right texel at 0.2.
  fm::ShadowMap map{4, std::vector<double>(16)};
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) map.depth[static_cast<std::size_t>(row * 4 + column)] = column < 2 ? 0.3 : 1.0;
  }
  map.depth[3] = 0.2;
  const scene::Shadows nearest{4, 0.0, scene::ShadowFilter::nearest};
  const scene::Shadows pcf{4, 0.0, scene::ShadowFilter::pcf2x2};

  CHECK(fm::shadow_factor(map, nearest, {0.1, 0.5, 0.5}) == 0.0);
  CHECK(fm::shadow_factor(map, nearest, {0.9, 0.1, 0.5}) == 1.0);
  CHECK(fm::shadow_factor(map, nearest, {0.9, 0.95, 0.5}) == 0.0);  // t near 1 reads the top row
  CHECK(fm::shadow_factor(map, {4, 0.25, scene::ShadowFilter::nearest}, {0.1, 0.5, 0.5}) == 1.0);  // bias
  CHECK(fm::shadow_factor(map, nearest, {0.1, 0.5, 0.3}) == 1.0);  // r/q - bias <= D: equal is lit

  CHECK(fm::shadow_factor(map, pcf, {0.5, 0.5, 0.5}) == Approx(0.5));  // x = 1.5: columns 1 and 2, half each
  CHECK(fm::shadow_factor(map, pcf, {0.4, 0.5, 0.5}) == Approx(0.1));  // x = 1.1: 10 % of column 2
  CHECK(fm::shadow_factor(map, pcf, {0.0, 0.5, 0.5}) == 0.0);          // x = -0.5: both clamp to column 0
  CHECK(fm::shadow_factor(map, pcf, {1.0, 0.05, 0.5}) == 1.0);         // clamped into the bottom-right texel
  CHECK(fm::shadow_factor(map, pcf, {0.9, 0.75, 0.5}) == Approx(0.5)); // y = 2.5: rows 2 and 3 from the bottom
  CHECK(fm::shadow_factor(map, pcf, {0.9, 0.875, 0.5}) == 0.0);        // y = 3.0: the top row only
}

namespace {

constexpr int image_size = 80;
constexpr double ambient = 0.2;

// Eye 10 above the floor looking straight down, seeing the floor from -2.5 to 2.5.
// Projector 2 above the floor, 90 degrees, pointing down: lights -2 .. 2. A
// 1 x 1 occluder 1 above the floor; its shadow on the floor spans -1 .. 1.
scene::Scene occluder_scene(scene::ShadowFilter filter, scene::Cull occluder_cull, bool occluder_faces_up) {
  const double fovy = 2.0 * glm::degrees(std::atan(0.25));
  scene::Scene s = spanlight::test::empty_scene(image_size, image_size, {0, 10, 0}, {0, 0, 0}, {0, 0, -1}, fovy, 1.0, 20.0);
  s.ambient = glm::dvec3(ambient);
  s.textures.push_back(spanlight::test::texture("white", spanlight::test::solid_image(4, 4, {255, 255, 255}),
                                                scene::Filter::nearest, scene::Wrap::clamp));
  s.objects.push_back(spanlight::test::quad("floor", {glm::dvec3(-4, 0, 4), glm::dvec3(4, 0, 4), glm::dvec3(4, 0, -4),
                                                      glm::dvec3(-4, 0, -4)}));
  s.objects[0].color = glm::dvec3(0.5);
  std::array<glm::dvec3, 4> square{glm::dvec3(-0.5, 1, 0.5), glm::dvec3(0.5, 1, 0.5), glm::dvec3(0.5, 1, -0.5),
                                   glm::dvec3(-0.5, 1, -0.5)};  // counter-clockwise seen from above
  if (!occluder_faces_up) std::reverse(square.begin(), square.end());
  s.objects.push_back(spanlight::test::quad("occluder", square));
  s.objects[1].color = {0.8, 0.4, 0.2};
  s.objects[1].cull = occluder_cull;
  scene::Projector p;
  p.name = "down";
  p.eye = {0, 2, 0};
  p.target = {0, 0, 0};
  p.up = {0, 0, -1};
  p.fovy_deg = 90.0;
  p.near = 0.5;
  p.far = 10.0;
  p.image = 0;
  p.shadows = scene::Shadows{256, 0.001, filter};
  s.projectors.push_back(p);
  return s;
}

enum class Expect { occluder_lit, floor_shadowed, floor_lit, floor_unlit, unsure };

// What the centre of pixel (px, py) must show, from the geometry alone.
Expect expected_at(int px, int py, bool occluder_visible) {
  const double x_ndc = (px + 0.5) / image_size * 2.0 - 1.0;
  const double y_ndc = 1.0 - (py + 0.5) / image_size * 2.0;
  const double margin = 1.5 * 2.0 / image_size;          // 1.5 pixels in NDC: room for snapping and map texels
  const double ndc = std::max(std::abs(x_ndc), std::abs(y_ndc));
  const double occluder_edge = 0.5 / (0.25 * 9.0);       // the occluder's edge, 9 below the eye
  if (occluder_visible && ndc < occluder_edge - margin) return Expect::occluder_lit;
  if (occluder_visible && ndc < occluder_edge + margin) return Expect::unsure;
  const double on_floor = ndc * 0.25 * 10.0;             // max(|x|, |z|) where the ray meets the floor
  const double floor_margin = margin * 0.25 * 10.0;
  const auto near_to = [&](double edge) { return std::abs(on_floor - edge) < floor_margin; };
  if (near_to(1.0) || near_to(2.0)) return Expect::unsure;
  if (on_floor > 2.0) return Expect::floor_unlit;  // outside the projector's frustum
  // The segment to the light (0, 2, 0) passes height 1 at half the distance.
  return occluder_visible && on_floor < 1.0 ? Expect::floor_shadowed : Expect::floor_lit;
}

void check_shadows(const scene::Scene& s, bool occluder_visible) {
  const fm::FloatFrame frame = fm::render_float(s);
  int counts[5] = {};
  for (int py = 0; py < image_size; ++py) {
    for (int px = 0; px < image_size; ++px) {
      const Expect expect = expected_at(px, py, occluder_visible);
      ++counts[static_cast<int>(expect)];
      if (expect == Expect::unsure) continue;
      const std::size_t i = static_cast<std::size_t>(py * image_size + px);
      INFO("pixel " << px << ", " << py << " expected case " << static_cast<int>(expect));
      CHECK(frame.object[i] == (expect == Expect::occluder_lit ? 1 : 0));
      const double light = frame.light_rgb[i * 3];
      const bool lit = expect == Expect::occluder_lit || expect == Expect::floor_lit;
      CHECK(light == Approx(lit ? 1.0 : ambient));
      if (expect == Expect::floor_shadowed) CHECK(frame.rgb[i * 3] == 26);  // round(255 * 0.2 * 0.5) = round(25.5)
      if (expect == Expect::floor_lit) CHECK(frame.rgb[i * 3] == 128);      // round(127.5)
      if (expect == Expect::occluder_lit) CHECK(frame.rgb[i * 3] == 204);   // round(255 * 0.8)
    }
  }
  // Each case really occurs.
  if (occluder_visible) {
    CHECK(counts[static_cast<int>(Expect::occluder_lit)] > 150);
    CHECK(counts[static_cast<int>(Expect::floor_shadowed)] > 300);
  }
  CHECK(counts[static_cast<int>(Expect::floor_lit)] > 1000);
  CHECK(counts[static_cast<int>(Expect::floor_unlit)] > 500);
}

}  // namespace

TEST_CASE("an occluder over a floor shadows exactly the floor beneath it (nearest)", "[shadow]") {
  check_shadows(occluder_scene(scene::ShadowFilter::nearest, scene::Cull::none, true), true);
}

TEST_CASE("an occluder over a floor shadows exactly the floor beneath it (pcf2x2)", "[shadow]") {
  check_shadows(occluder_scene(scene::ShadowFilter::pcf2x2, scene::Cull::none, true), true);
}

TEST_CASE("the shadow pass honours each object's cull setting", "[shadow][culling]") {
  // Facing up and culled: front-facing for eye and projector alike, casts its shadow.
  check_shadows(occluder_scene(scene::ShadowFilter::nearest, scene::Cull::back, true), true);
  // Facing down and culled: neither the eye nor the projector draws it, no shadow.
  check_shadows(occluder_scene(scene::ShadowFilter::nearest, scene::Cull::back, false), false);
}
