// facing_only: a projector behind a wall lights nothing with it and shows through
// without it; one on the camera's side lights the wall either way; one whose eye lies
// in the wall's plane is on neither side and lights nothing with it.
#include <catch2/catch.hpp>

#include "effect_scenes.hpp"
#include "picture_check.hpp"

using namespace spanlight;
using namespace spanlight::effects;

namespace {

// The wall [-1, 1]^2 of the plane z = 0 (pixels 24..39), white, ambient 0.25, one projector of
// colour 0.5 with a white image covering the whole wall: lit pixels are 0.75 -> 191, unlit
// ones 0.25 -> 64, the background 0.
scene::Scene wall_with(scene::Projector p) {
  scene::Scene s = head_on_scene();
  s.ambient = glm::dvec3(0.25);
  const int white = add_texture(s, "white", grey_image(4, 4, std::vector<int>(16, 255)), scene::Filter::bilinear,
                                scene::Wrap::clamp);
  s.objects.push_back(rectangle("wall", -1, -1, 1, 1));
  p.image = white;
  p.color = glm::dvec3(0.5);
  s.projectors.push_back(p);
  return s;
}

void check_wall(const EffectRenderer& renderer, const scene::Scene& s, bool lit) {
  const Picture picture = renderer.render(s);
  const Mismatches m = compare_grey(picture, [&](int x, int y) {
    if (!inside(x, y, -1, -1, 1, 1)) return 0;
    return byte_of(lit ? 0.75 : 0.25);
  }, renderer.value_lsb);
  INFO(renderer.name << ": " << m.first);
  CHECK(m.checked == side * side);
  CHECK(m.count == 0);
}

}  // namespace

TEST_CASE("facing_only: a projector behind a wall lights nothing, and without it the light shows through", "[effects][facing]") {
  // The slide projector of v2_facing_wall, head-on: 3 units behind the wall, aimed at it.
  // Its frustum (fovy 90) holds the whole wall: s/q, t/q in [1/3, 2/3], inside the white image.
  scene::Projector behind = projector({0, 0, -3}, {0, 0, 0}, 90, 0.5, 20, -1);
  for (const EffectRenderer& renderer : effect_renderers()) {
    check_wall(renderer, wall_with(behind), true);
    behind.facing_only = true;
    check_wall(renderer, wall_with(behind), false);
    behind.facing_only = false;
  }
}

TEST_CASE("facing_only: a projector on the camera's side lights the wall", "[effects][facing]") {
  scene::Projector front = projector({0.5, 0.25, 3}, {0, 0, 0}, 90, 0.5, 20, -1);
  front.facing_only = true;
  for (const EffectRenderer& renderer : effect_renderers()) check_wall(renderer, wall_with(front), true);
}

TEST_CASE("facing_only: an eye in the wall's plane is on neither side", "[effects][facing]") {
  // From (-3, 0, 0) along +x the wall is seen edge-on: every wall point projects to s/q = 0.5
  // and t/q = 0.5 + 0.5 y / (x + 3) in [0.25, 0.75], inside the image, so without facing_only
  // it is lit; with it, the projector's eye lies in the plane and lights nothing.
  scene::Projector grazing = projector({-3, 0, 0}, {0, 0, 0}, 90, 0.5, 20, -1);
  for (const EffectRenderer& renderer : effect_renderers()) {
    check_wall(renderer, wall_with(grazing), true);
    grazing.facing_only = true;
    check_wall(renderer, wall_with(grazing), false);
    grazing.facing_only = false;
  }
}
