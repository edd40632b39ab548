// Scene format 2 in the light equation: falloff(r/q) and facing_only. Whole pictures
// of these effects are in tests/effects.
#include <cmath>

#include <catch2/catch.hpp>

#include "float_model/facing.hpp"
#include "float_model/sample.hpp"
#include "float_model/shade.hpp"
#include "test_scenes.hpp"

namespace fm = spanlight::float_model;
namespace scene = spanlight::scene;

namespace {

// A 4x1 grey ramp 0, 80, 160, 240.
scene::Image ramp() { return scene::Image{4, 1, {0, 0, 0, 80, 80, 80, 160, 160, 160, 240, 240, 240}}; }

}  // namespace

TEST_CASE("falloff is sampled at (r/q, 0.5) with its own filter, clamped to its edge", "[light][v2]") {
  for (const scene::Wrap wrap : {scene::Wrap::repeat, scene::Wrap::border}) {  // the texture's wrap is ignored
    const auto nearest = spanlight::test::texture("ramp", ramp(), scene::Filter::nearest, wrap);
    CHECK(fm::sample_falloff(nearest, 0.0).r * 255 == Approx(0.0));
    CHECK(fm::sample_falloff(nearest, 0.3).r * 255 == Approx(80.0));   // texel floor(0.3 * 4) = 1
    CHECK(fm::sample_falloff(nearest, 1.0).r * 255 == Approx(240.0));  // clamped, not wrapped to texel 0
    const auto bilinear = spanlight::test::texture("ramp", ramp(), scene::Filter::bilinear, wrap);
    CHECK(fm::sample_falloff(bilinear, 0.0).r * 255 == Approx(0.0));    // half a texel beyond texel 0's centre: clamped
    CHECK(fm::sample_falloff(bilinear, 0.5).r * 255 == Approx(120.0));  // between texels 1 and 2
    CHECK(fm::sample_falloff(bilinear, 1.0).r * 255 == Approx(240.0));
    // Never mipmapped: trilinear reads level 0 bilinearly.
    const auto trilinear = spanlight::test::texture("ramp", ramp(), scene::Filter::trilinear, wrap);
    for (const double depth : {0.0, 0.2, 0.45, 0.8, 1.0}) {
      CHECK(fm::sample_falloff(trilinear, depth) == fm::sample_falloff(bilinear, depth));
    }
  }
}

TEST_CASE("a projector's light is multiplied by its falloff at r/q", "[light][v2]") {
  scene::Scene s;
  s.textures.push_back(spanlight::test::texture("white", spanlight::test::solid_image(2, 2, {255, 255, 255}),
                                                scene::Filter::nearest, scene::Wrap::repeat));
  s.textures.push_back(spanlight::test::texture("ramp", ramp(), scene::Filter::nearest, scene::Wrap::clamp));
  scene::Projector p;
  p.image = 0;
  p.color = {1.0, 0.5, 2.0};
  for (const double depth : {0.1, 0.3, 0.6, 0.9}) {
    const glm::dvec4 strq = glm::dvec4(0.5, 0.5, depth, 1.0) * 2.0;  // q = 2: r/q = depth
    p.falloff = -1;
    const glm::dvec3 plain = fm::projector_light(s, p, nullptr, strq);
    p.falloff = 1;
    const glm::dvec3 dimmed = fm::projector_light(s, p, nullptr, strq);
    const double expected = std::floor(depth * 4) * 80.0 / 255.0;
    CHECK(dimmed.r == Approx(plain.r * expected));
    CHECK(dimmed.g == Approx(plain.g * expected));
    CHECK(dimmed.b == Approx(plain.b * expected));
  }
  // Outside the frustum falloff does not bring light back.
  CHECK(fm::projector_light(s, p, nullptr, {0.5, 0.5, 1.5, 1.0}) == glm::dvec3(0.0));
  // A triangle facing_only keeps away gets none.
  CHECK(fm::projector_light(s, p, nullptr, {0.5, 0.5, 0.9, 1.0}, false) == glm::dvec3(0.0));
}

TEST_CASE("facing: both eyes strictly on the same side of the triangle's plane", "[light][v2]") {
  const std::array<glm::dvec3, 3> wall{glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0)};  // z = 0
  CHECK(fm::strictly_same_side(wall, {0, 0, 5}, {3, -2, 1}));
  CHECK(fm::strictly_same_side(wall, {0, 0, -5}, {3, -2, -1}));
  CHECK_FALSE(fm::strictly_same_side(wall, {0, 0, 5}, {0, 0, -1}));
  CHECK_FALSE(fm::strictly_same_side(wall, {0, 0, 5}, {7, 3, 0}));    // an eye in the plane: neither side
  CHECK_FALSE(fm::strictly_same_side(wall, {7, 3, 0}, {7, 3, 0}));
  const std::array<glm::dvec3, 3> degenerate{glm::dvec3(0, 0, 0), glm::dvec3(1, 1, 1), glm::dvec3(2, 2, 2)};
  CHECK_FALSE(fm::strictly_same_side(degenerate, {0, 0, 5}, {0, 0, 6}));  // no plane: never lit
  // The winding does not matter: the test compares two sides of one plane.
  const std::array<glm::dvec3, 3> flipped{wall[0], wall[2], wall[1]};
  CHECK(fm::strictly_same_side(flipped, {0, 0, 5}, {3, -2, 1}));
}

TEST_CASE("projectors_facing: after M, with a camera-space projector's eye in world space", "[light][v2]") {
  scene::Scene s = spanlight::test::empty_scene(8, 8, {0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60, 0.1, 100);
  scene::Object wall = spanlight::test::quad("wall", {glm::dvec3(-1, -1, 0), glm::dvec3(1, -1, 0), glm::dvec3(1, 1, 0),
                                                      glm::dvec3(-1, 1, 0)});
  wall.model = glm::dmat4(1.0);
  wall.model[3] = glm::dvec4(0, 0, 2, 1);  // moved to z = 2
  scene::Projector front, behind, plain, headlight;
  front.eye = {0, 0, 4};
  front.facing_only = true;
  behind.eye = {0, 0, 1};  // behind the moved wall (in front of it before M)
  behind.facing_only = true;
  plain.eye = {0, 0, 1};   // the same place without facing_only
  headlight.space = scene::ProjectorSpace::camera;
  headlight.eye = {0, 0, -4};  // 4 in front of the camera: world z = 1, behind the wall
  headlight.facing_only = true;
  s.projectors = {front, behind, plain, headlight};
  for (std::size_t triangle = 0; triangle < 2; ++triangle) {
    CHECK(fm::projectors_facing(s, wall, triangle) == std::vector<std::uint8_t>{1, 0, 1, 0});
  }
}
