// The matrices the spec defines: model (T * Rz * Ry * Rx * S or the given
// column-major matrix), camera perspective * lookAt, projector B * P * V.
#include <cmath>

#include <catch2/catch.hpp>

#include "catch_glm.hpp"
#include "scene/scene.hpp"
#include "scratch_folder.hpp"
#include "source_paths.hpp"

using namespace spanlight::scene;
using spanlight::scene::test::example_scene;
using spanlight::scene::test::ScratchFolder;

namespace {

constexpr double pi = 3.14159265358979323846;

// Written out by hand rather than with glm::rotate, so the test does not
// share the loader's way of building it. Rows as one reads them on paper.
glm::dmat4 from_rows(const std::array<std::array<double, 4>, 4>& rows) {
  glm::dmat4 m(0.0);
  for (glm::length_t r = 0; r < 4; ++r) {
    for (glm::length_t c = 0; c < 4; ++c) m[c][r] = rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
  }
  return m;
}

glm::dmat4 translation(glm::dvec3 t) { return from_rows({{{1, 0, 0, t.x}, {0, 1, 0, t.y}, {0, 0, 1, t.z}, {0, 0, 0, 1}}}); }
glm::dmat4 scaling(glm::dvec3 s) { return from_rows({{{s.x, 0, 0, 0}, {0, s.y, 0, 0}, {0, 0, s.z, 0}, {0, 0, 0, 1}}}); }
glm::dmat4 rotation_x(double degrees) {
  const double c = std::cos(degrees * pi / 180), s = std::sin(degrees * pi / 180);
  return from_rows({{{1, 0, 0, 0}, {0, c, -s, 0}, {0, s, c, 0}, {0, 0, 0, 1}}});
}
glm::dmat4 rotation_y(double degrees) {
  const double c = std::cos(degrees * pi / 180), s = std::sin(degrees * pi / 180);
  return from_rows({{{c, 0, s, 0}, {0, 1, 0, 0}, {-s, 0, c, 0}, {0, 0, 0, 1}}});
}
glm::dmat4 rotation_z(double degrees) {
  const double c = std::cos(degrees * pi / 180), s = std::sin(degrees * pi / 180);
  return from_rows({{{c, -s, 0, 0}, {s, c, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}});
}

void check_close(const glm::dmat4& actual, const glm::dmat4& expected) {
  for (glm::length_t c = 0; c < 4; ++c) {
    for (glm::length_t r = 0; r < 4; ++r) {
      INFO("column " << c << " row " << r);
      CHECK(actual[c][r] == Approx(expected[c][r]).margin(1e-12));
    }
  }
}

glm::dvec3 project(const glm::dmat4& matrix, glm::dvec3 point) {
  const glm::dvec4 clip = matrix * glm::dvec4(point, 1.0);
  return glm::dvec3(clip) / clip.w;
}

Scene scene_with_transform(const ScratchFolder& folder, const std::string& transform) {
  return load_scene(folder.write("scene.json", R"({
    "spanlight_scene": 1, "output": { "width": 8, "height": 8 },
    "camera": { "eye": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 60, "near": 0.1, "far": 10 },
    "objects": [ { "positions": [[0, 0, 0]], "triangles": [], "transform": )" + transform + " } ] }"));
}

}  // namespace

TEST_CASE("model matrix of translate/rotate_deg/scale is T * Rz * Ry * Rx * S", "[scene][matrix]") {
  const ScratchFolder folder;
  const Scene scene = scene_with_transform(
      folder, R"({ "translate": [1, -2, 3], "rotate_deg": [10, 20, 30], "scale": [2, 3, 4] })");
  const glm::dmat4 expected = translation({1, -2, 3}) * rotation_z(30) * rotation_y(20) * rotation_x(10) *
                              scaling({2, 3, 4});
  check_close(scene.objects[0].model, expected);
}

TEST_CASE("the example crates get T * Rz * Ry * Rx * S", "[scene][matrix]") {
  const Scene slide = load_scene(example_scene("slide_projector.json"));
  check_close(slide.objects[1].model, translation({-1.2, 0, -1.5}) * rotation_y(30) * scaling(glm::dvec3(1.4)));
  const Scene spot = load_scene(example_scene("spot_shadow.json"));
  check_close(spot.objects[1].model, translation({0.8, 0, -0.8}) * rotation_y(20) * scaling({1, 1.6, 1}));
  check_close(spot.objects[2].model, translation({-1.2, 0.7, 0.3}) * scaling(glm::dvec3(0.7)));
}

TEST_CASE("a transform matrix is read column by column", "[scene][matrix]") {
  const ScratchFolder folder;
  const Scene scene = scene_with_transform(
      folder, R"({ "matrix": [1, 0, 0, 0,  0, 2, 0, 0,  0, 0, 3, 0,  7, 8, 9, 1] })");
  CHECK(scene.objects[0].model * glm::dvec4(1, 1, 1, 1) == glm::dvec4(8, 10, 12, 1));
}

TEST_CASE("the camera projects its target to the centre, near to depth -1, far to +1", "[scene][matrix]") {
  const Scene scene = load_scene(example_scene("slide_projector.json"));
  const glm::dmat4 view_projection = camera_view_projection(scene);
  const Camera& camera = scene.camera;
  const glm::dvec3 forward = glm::normalize(camera.target - camera.eye);

  const glm::dvec3 centre = project(view_projection, camera.target);
  CHECK(centre.x == Approx(0.0).margin(1e-12));
  CHECK(centre.y == Approx(0.0).margin(1e-12));
  CHECK(project(view_projection, camera.eye + camera.near * forward).z == Approx(-1.0));
  CHECK(project(view_projection, camera.eye + camera.far * forward).z == Approx(1.0));

  // Half the vertical field of view above the axis is the top edge, y = 1;
  // the horizontal extent follows width / height.
  const glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
  const glm::dvec3 up = glm::cross(right, forward);
  const double half_height = std::tan(camera.fovy_deg * pi / 360);
  const double aspect = 320.0 / 240.0;
  CHECK(project(view_projection, camera.eye + forward + half_height * up).y == Approx(1.0));
  CHECK(project(view_projection, camera.eye + forward + half_height * aspect * right).x == Approx(1.0));
}

TEST_CASE("a projector's texture matrix maps its frustum to [0, 1]", "[scene][matrix]") {
  const Scene scene = load_scene(example_scene("horizon.json"));
  const Projector& projector = scene.projectors[0];  // aspect 2
  const glm::dmat4 texture_matrix = projector_texture_matrix(scene.camera, projector);
  const glm::dvec3 forward = glm::normalize(projector.target - projector.eye);

  const glm::dvec3 centre = project(texture_matrix, projector.target);
  CHECK(centre.x == Approx(0.5));
  CHECK(centre.y == Approx(0.5));
  CHECK(project(texture_matrix, projector.eye + projector.near * forward).z == Approx(0.0).margin(1e-12));
  CHECK(project(texture_matrix, projector.eye + projector.far * forward).z == Approx(1.0));

  const glm::dvec3 right = glm::normalize(glm::cross(forward, projector.up));
  const double half_height = std::tan(projector.fovy_deg * pi / 360);
  CHECK(project(texture_matrix, projector.eye + forward + half_height * projector.aspect * right).x == Approx(1.0));

  // B itself: [-1, 1] to [0, 1] on x, y and z, w kept.
  const glm::dmat4 bias = from_rows({{{0.5, 0, 0, 0.5}, {0, 0.5, 0, 0.5}, {0, 0, 0.5, 0.5}, {0, 0, 0, 1}}});
  check_close(texture_matrix, bias * projector_view_projection(scene.camera, projector));
}
