// space: camera. A projector at the camera's eye with the camera's frustum lights every
// pixel with the same texel whatever the camera's pose (and whatever it looks at); a
// shadowed camera-space light is unchanged when camera and scene move rigidly together,
// while a world-space light left behind changes.
#include <cmath>

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "effect_scenes.hpp"
#include "picture_check.hpp"

using namespace spanlight;
using namespace spanlight::effects;

namespace {

// The inside of the box [-5, 5]^3, white: the camera inside sees a surface at every pixel.
void add_box(scene::Scene& s) {
  const double a = 5.0;
  s.objects.push_back(rectangle("back", -a, -a, a, a, -a));
  s.objects.push_back(rectangle("front", -a, -a, a, a, a));
  for (int axis = 0; axis < 2; ++axis) {
    for (const double side_sign : {-1.0, 1.0}) {
      scene::Object wall = rectangle("side", -a, -a, a, a, 0.0);
      // Turn the z = 0 rectangle to x = +-a (axis 0) or y = +-a (axis 1).
      const glm::dvec3 turn_axis = axis == 0 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
      const glm::dvec3 shift = axis == 0 ? glm::dvec3(side_sign * a, 0, 0) : glm::dvec3(0, side_sign * a, 0);
      wall.model = glm::translate(glm::dmat4(1.0), shift) * glm::rotate(glm::dmat4(1.0), glm::radians(90.0), turn_axis);
      s.objects.push_back(wall);
    }
  }
}

}  // namespace

TEST_CASE("a camera-space headlight lights the same pixels with the same texels in every camera pose", "[effects][headlight]") {
  // The headlight sits at the camera's eye and has the camera's fovy and aspect, so a pixel's
  // (s/q, t/q) is its centre's position in the picture: ((px + 0.5) / 64, 1 - (py + 0.5) / 64).
  // Its 8 x 8 nearest image puts 8 x 8 pixels in each texel, every centre 1/16 texel or more
  // from a texel edge. Light = 0.2 + texel: byte 51 + texel (texels 20..146, no clamp).
  std::vector<int> texels;
  for (int i = 0; i < 64; ++i) texels.push_back(20 + 2 * i);
  scene::Scene s = head_on_scene();
  s.camera.fovy_deg = 60;
  s.camera.near = 0.1;
  s.camera.far = 100;
  s.ambient = glm::dvec3(0.2);
  const int image = add_texture(s, "pattern", grey_image(8, 8, texels), scene::Filter::nearest, scene::Wrap::clamp);
  add_box(s);
  scene::Projector headlight = projector({0, 0, 0}, {0, 0, -1}, 60, 0.05, 100, image);
  headlight.space = scene::ProjectorSpace::camera;
  s.projectors.push_back(headlight);

  const auto expected = [&](int x, int y) {
    const int column = (2 * x + 1) / 16;           // floor(8 * (x + 0.5) / 64)
    const int row_from_bottom = (2 * (63 - y) + 1) / 16;
    return 51 + texels[static_cast<std::size_t>((7 - row_from_bottom) * 8 + column)];
  };
  const std::vector<std::pair<glm::dvec3, glm::dvec3>> poses = {
      {{0, 0, 0}, {0, 0, -1}}, {{1, -0.5, 2}, {3, 1, -4}}, {{-2, 1, -1}, {1, -2, 3}}, {{3.5, 3, 3}, {-4, -2, -3}}};
  for (const EffectRenderer& renderer : effect_renderers()) {
    for (const auto& [eye, target] : poses) {
      s.camera.eye = eye;
      s.camera.target = target;
      const Mismatches m = compare_grey(renderer.render(s), expected, renderer.value_lsb);
      INFO(renderer.name << ", camera at " << eye.x << ", " << eye.y << ", " << eye.z << ": " << m.first);
      CHECK(m.checked == side * side);
      CHECK(m.count == 0);
    }
  }
}

namespace {

// A floor with a block above it, lit by a shadowed light beside the camera.
scene::Scene shadow_scene(scene::ProjectorSpace space) {
  scene::Scene s = head_on_scene();
  s.camera = scene::Camera{{0, 2.5, 4}, {0, 0, 0}, {0, 1, 0}, 60, 0.1, 50};
  // Binary fractions (ambient 1/8, light 3/4): a lit pixel is 7/8 -> 223.125, unlit 1/8 -> 31.875, far
  // from the ties at which rounding 1e-15 apart could give two bytes.
  s.ambient = glm::dvec3(0.125);
  const int white = add_texture(s, "white", grey_image(4, 4, std::vector<int>(16, 255)), scene::Filter::bilinear,
                                scene::Wrap::clamp);
  scene::Object floor = rectangle("floor", -4, -4, 4, 4);
  floor.model = glm::rotate(glm::dmat4(1.0), glm::radians(-90.0), glm::dvec3(1, 0, 0));  // the plane y = 0, facing up
  s.objects.push_back(floor);
  scene::Object block = rectangle("block", -0.6, -0.6, 0.6, 0.6);
  block.model = glm::translate(glm::dmat4(1.0), glm::dvec3(0.3, 1.0, 0.2)) * floor.model;  // a lid at y = 1
  s.objects.push_back(block);
  scene::Projector light = projector({0.8, 0.6, 0}, {0, -0.4, -4}, 70, 0.5, 30, white, glm::dvec3(0.75));
  light.shadows = scene::Shadows{256, 0.003, scene::ShadowFilter::nearest};
  light.space = scene::ProjectorSpace::camera;
  if (space == scene::ProjectorSpace::world) {  // the same light, given in world coordinates
    const glm::dmat4 world_from_eye = glm::inverse(scene::camera_view(s.camera));
    light.eye = glm::dvec3(world_from_eye * glm::dvec4(light.eye, 1.0));
    light.target = glm::dvec3(world_from_eye * glm::dvec4(light.target, 1.0));
    light.up = glm::dvec3(world_from_eye * glm::dvec4(light.up, 0.0));
    light.space = space;
  }
  s.projectors.push_back(light);
  return s;
}

// Camera and objects moved by the rigid motion T; projectors stay as given.
scene::Scene moved(scene::Scene s, const glm::dmat4& t) {
  s.camera.eye = glm::dvec3(t * glm::dvec4(s.camera.eye, 1.0));
  s.camera.target = glm::dvec3(t * glm::dvec4(s.camera.target, 1.0));
  s.camera.up = glm::dvec3(t * glm::dvec4(s.camera.up, 0.0));
  for (scene::Object& o : s.objects) o.model = t * o.model;
  return s;
}

// Pixels whose bytes differ by more than `lsb` in some channel.
int pixels_differing(const Picture& a, const Picture& b, int lsb) {
  int count = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c)
        if (std::abs(a.channel(x, y, c) - b.channel(x, y, c)) > lsb) {
          ++count;
          break;
        }
  return count;
}

}  // namespace

TEST_CASE("a shadowed camera-space light is unchanged by a rigid motion of camera and scene, a world-space one is not",
          "[effects][headlight]") {
  const glm::dmat4 motion = glm::translate(glm::dmat4(1.0), glm::dvec3(2.0, 0.5, -1.0)) *
                            glm::rotate(glm::dmat4(1.0), glm::radians(30.0), glm::dvec3(0.2, 1.0, 0.1));
  for (const EffectRenderer& renderer : effect_renderers()) {
    INFO(renderer.name);
    const int allowed = static_cast<int>(renderer.rigid_motion_pixel_fraction * side * side);
    const Picture camera_space = renderer.render(shadow_scene(scene::ProjectorSpace::camera));
    const Picture world_space = renderer.render(shadow_scene(scene::ProjectorSpace::world));
    // The picture holds lit surfaces and unlit ones (ambient only: the lid's shadow, beyond the light).
    int lit = 0, unlit = 0;
    for (int y = 0; y < side; ++y) {
      for (int x = 0; x < side; ++x) {
        const int v = camera_space.channel(x, y, 0);
        if (v > 150) ++lit;
        if (v > 0 && v < 40) ++unlit;
      }
    }
    CHECK(lit > 200);
    CHECK(unlit > 20);
    const Picture camera_space_moved = renderer.render(moved(shadow_scene(scene::ProjectorSpace::camera), motion));
    CHECK(pixels_differing(camera_space, camera_space_moved, renderer.value_lsb) <= allowed);
    // Before the motion, the world-space light posed where the camera-space one is draws the same picture.
    CHECK(pixels_differing(camera_space, world_space, renderer.value_lsb) <= allowed);
    // Left behind by the motion, it draws another one.
    const Picture world_left_behind = renderer.render(moved(shadow_scene(scene::ProjectorSpace::world), motion));
    CHECK(pixels_differing(camera_space, world_left_behind, 8) > side * side / 20);
  }
}
