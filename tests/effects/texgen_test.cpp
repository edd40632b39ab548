// texgen: stripes from a 4-texel stripe texture land on the level sets of the planes,
// in object coordinates (they move with the object) or in the camera's eye
// coordinates (they stay on the screen when the camera moves).
#include <cmath>

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "effect_scenes.hpp"
#include "picture_check.hpp"

using namespace spanlight;
using namespace spanlight::effects;

namespace {

// White, white, black, black: u in [k, k + 1/2) is white, [k + 1/2, k + 1) black (nearest, repeat).
// Ambient 1 and a white light-less scene: a pixel is its texel.
scene::Scene striped_wall(scene::Texgen texgen, double camera_x) {
  scene::Scene s = head_on_scene();
  s.camera.eye.x = camera_x;
  s.camera.target.x = camera_x;
  s.ambient = glm::dvec3(1.0);
  const int stripes = add_texture(s, "stripes", grey_image(4, 1, {255, 255, 0, 0}), scene::Filter::nearest, scene::Wrap::repeat);
  // The wall [-3, 3]^2 of the plane z = 0, given in object coordinates shifted by -0.25 in x.
  scene::Object wall = rectangle("wall", -3.25, -3, 2.75, 3);
  wall.model = glm::translate(glm::dmat4(1.0), glm::dvec3(0.25, 0, 0));
  wall.texture = stripes;
  wall.texgen = texgen;
  s.objects.push_back(wall);
  return s;
}

// The expected byte at a pixel whose u is known; -1 within the renderer's error of a texel edge.
int stripe_byte(double u, double error) {
  const double texel = 4.0 * u;  // in texels of the 4-texel image
  if (std::abs(texel - std::round(texel)) <= error) return -1;
  const long long k = static_cast<long long>(std::floor(texel));
  return ((k % 4) + 4) % 4 < 2 ? 255 : 0;
}

}  // namespace

TEST_CASE("object-space texgen stripes lie on the planes' level sets in object coordinates", "[effects][texgen]") {
  const scene::Texgen planes{{0.5, 0.25, 0, 0.125}, {0, 0, 0, 0}, scene::TexgenSpace::object};
  for (const EffectRenderer& renderer : effect_renderers()) {
    for (const double camera_x : {0.0, 1.0}) {  // the camera moves: the stripes stay on the wall
      const Mismatches m = compare_grey(renderer.render(striped_wall(planes, camera_x)), [&](int x, int y) {
        const glm::dvec2 p = plane_point(x, y) + glm::dvec2(camera_x, 0);
        if (!(std::abs(p.x) < 3 && std::abs(p.y) < 3)) return 0;
        const double object_x = p.x - 0.25;  // the model matrix shifts the wall by 0.25
        return stripe_byte(0.5 * object_x + 0.25 * p.y + 0.125, renderer.texel_coordinate_error);
      }, renderer.value_lsb);
      INFO(renderer.name << ", camera x " << camera_x << ": " << m.first);
      CHECK(m.checked > 2000);
      CHECK(m.count == 0);
    }
  }
}

TEST_CASE("eye-space texgen stripes lie on the planes' level sets in eye coordinates", "[effects][texgen]") {
  // u = 0.5 x_eye + 0.25 z_eye + 1; on the wall z_eye = -4, so u = 0.5 x_eye: fixed to the screen.
  const scene::Texgen planes{{0.5, 0, 0.25, 1.0}, {0, 1, 0, 0}, scene::TexgenSpace::eye};
  for (const EffectRenderer& renderer : effect_renderers()) {
    for (const double camera_x : {0.0, 1.0}) {
      const Mismatches m = compare_grey(renderer.render(striped_wall(planes, camera_x)), [&](int x, int y) {
        const glm::dvec2 p = plane_point(x, y) + glm::dvec2(camera_x, 0);
        if (!(std::abs(p.x) < 3 && std::abs(p.y) < 3)) return 0;
        const double eye_x = p.x - camera_x;
        return stripe_byte(0.5 * eye_x + 0.25 * -4.0 + 1.0, renderer.texel_coordinate_error);
      }, renderer.value_lsb);
      INFO(renderer.name << ", camera x " << camera_x << ": " << m.first);
      CHECK(m.checked > 2000);
      CHECK(m.count == 0);
    }
  }
}
