// The light equation: the frustum conditions (q > 0 first of all), ambient plus
// projectors clamped to 1, times the surface, rounded to bytes.
#include <catch2/catch.hpp>

#include <algorithm>

#include "float_model/float_model.hpp"
#include "float_model/shade.hpp"
#include "test_scenes.hpp"

namespace fm = spanlight::float_model;
namespace scene = spanlight::scene;

TEST_CASE("a point is in the projector's frustum only when q > 0 and s/q, t/q, r/q are in [0, 1]", "[light]") {
  CHECK(fm::project_into_frustum({0.5, 0.25, 0.75, 1.0}) == glm::dvec3(0.5, 0.25, 0.75));
  CHECK(fm::project_into_frustum({1.0, 0.5, 1.0, 2.0}) == glm::dvec3(0.5, 0.25, 0.5));
  // Behind the projector: every ratio is in range, but q < 0 means no back-projection.
  CHECK_FALSE(fm::project_into_frustum({-0.5, -0.25, -0.75, -1.0}));
  CHECK_FALSE(fm::project_into_frustum({0.0, 0.0, 0.0, 0.0}));
  // The borders of the frustum are in, just outside is out.
  CHECK(fm::project_into_frustum({0.0, 0.0, 0.0, 1.0}));
  CHECK(fm::project_into_frustum({1.0, 1.0, 1.0, 1.0}));
  CHECK_FALSE(fm::project_into_frustum({1.001, 0.5, 0.5, 1.0}));
  CHECK_FALSE(fm::project_into_frustum({0.5, -0.001, 0.5, 1.0}));
  CHECK_FALSE(fm::project_into_frustum({0.5, 0.5, 1.001, 1.0}));  // beyond the far plane
}

TEST_CASE("light is ambient plus each projector's colour times its image, clamped to 1 per channel", "[light]") {
  scene::Scene s;
  s.ambient = {0.1, 0.2, 0.3};
  s.textures.push_back(spanlight::test::texture("grey", spanlight::test::solid_image(2, 2, {51, 102, 204}),
                                                scene::Filter::nearest, scene::Wrap::repeat));
  scene::Projector p;
  p.image = 0;
  p.color = {2.0, 1.0, 0.5};
  s.projectors = {p};
  const glm::dvec4 inside(0.25, 0.25, 0.5, 1.0);
  const glm::dvec3 light = fm::pixel_light(s, {fm::ShadowMap{}}, {inside});
  CHECK(light.r == Approx(0.1 + 2.0 * 0.2));
  CHECK(light.g == Approx(0.2 + 1.0 * 0.4));
  CHECK(light.b == Approx(0.3 + 0.5 * 0.8));
  s.projectors.push_back(p);  // twice as much: blue goes over 1 and is clamped
  const glm::dvec3 doubled = fm::pixel_light(s, {fm::ShadowMap{}, fm::ShadowMap{}}, {inside, inside});
  CHECK(doubled.r == Approx(0.1 + 2 * 2.0 * 0.2));
  CHECK(doubled.g == Approx(1.0));
  CHECK(doubled.b == 1.0);
  CHECK(fm::pixel_light(s, {fm::ShadowMap{}, fm::ShadowMap{}}, {-inside, -inside}) == s.ambient);
}

TEST_CASE("the surface is the object colour times its texture, and bytes are round(255 * value)", "[light]") {
  scene::Scene s;
  s.textures.push_back(spanlight::test::texture("t", spanlight::test::solid_image(1, 1, {255, 128, 0}),
                                                scene::Filter::nearest, scene::Wrap::repeat));
  scene::Object plain;
  plain.color = {0.5, 0.25, 1.0};
  CHECK(fm::surface_color(s, plain, {0.5, 0.5}) == plain.color);
  scene::Object textured = plain;
  textured.texture = 0;
  const glm::dvec3 surface = fm::surface_color(s, textured, {0.5, 0.5});
  CHECK(surface.r == Approx(0.5));
  CHECK(surface.g == Approx(0.25 * 128.0 / 255.0));
  CHECK(surface.b == 0.0);
  CHECK(fm::to_byte(0.0) == 0);
  CHECK(fm::to_byte(1.0) == 255);
  CHECK(fm::to_byte(1.7) == 255);
  CHECK(fm::to_byte(-0.2) == 0);
  CHECK(fm::to_byte(0.5) == 128);  // 127.5 rounds half away from zero
  CHECK(fm::to_byte(100.4 / 255.0) == 100);
}

namespace {

// A grey floor y = 0 seen from straight above; one white projector 1 unit over
// its middle, pointing `down` or up.
scene::Scene floor_under_projector(bool down) {
  scene::Scene s = spanlight::test::empty_scene(32, 32, {0, 6, 0}, {0, 0, 0}, {0, 0, -1}, 60.0, 1.0, 20.0);
  s.ambient = glm::dvec3(0.25);
  s.textures.push_back(spanlight::test::texture("white", spanlight::test::solid_image(4, 4, {255, 255, 255}),
                                                scene::Filter::nearest, scene::Wrap::clamp));
  s.objects.push_back(spanlight::test::quad("floor", {glm::dvec3(-5, 0, 5), glm::dvec3(5, 0, 5), glm::dvec3(5, 0, -5),
                                                      glm::dvec3(-5, 0, -5)}));
  scene::Projector p;
  p.name = "lamp";
  p.eye = {0, 1, 0};
  p.target = down ? glm::dvec3(0, 0, 0) : glm::dvec3(0, 2, 0);
  p.up = {0, 0, -1};
  p.fovy_deg = 120.0;
  p.near = 0.1;
  p.far = 50.0;
  p.image = 0;
  s.projectors.push_back(p);
  return s;
}

}  // namespace

TEST_CASE("a projector pointing away from the geometry lights nothing (q <= 0 there)", "[light]") {
  const fm::FloatFrame away = fm::render_float(floor_under_projector(false));
  REQUIRE(std::count(away.object.begin(), away.object.end(), 0) == 32 * 32);
  for (const float light : away.light_rgb) CHECK(light == Approx(0.25));
  // The same projector turned toward the floor does light it: the test can fail.
  const fm::FloatFrame toward = fm::render_float(floor_under_projector(true));
  CHECK(std::count_if(toward.light_rgb.begin(), toward.light_rgb.end(), [](float l) { return l == 1.0f; }) > 100);
}
