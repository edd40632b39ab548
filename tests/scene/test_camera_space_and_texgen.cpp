// The version-2 derivations both backends share (scene.hpp): a camera-space
// projector's matrices and eye, and texgen uvs.
#include <cmath>
#include <random>

#include <catch2/catch.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "catch_glm.hpp"
#include "scene/scene.hpp"

using namespace spanlight::scene;

namespace {

Projector projector_at(glm::dvec3 eye, glm::dvec3 target, ProjectorSpace space) {
  Projector p;
  p.eye = eye;
  p.target = target;
  p.up = {0, 1, 0};
  p.fovy_deg = 40;
  p.near = 0.5;
  p.far = 20;
  p.space = space;
  return p;
}

Camera camera_at(glm::dvec3 eye, glm::dvec3 target) {
  Camera c;
  c.eye = eye;
  c.target = target;
  c.up = {0, 1, 0};
  return c;
}

void check_close(const glm::dmat4& actual, const glm::dmat4& expected, double margin) {
  for (glm::length_t c = 0; c < 4; ++c)
    for (glm::length_t r = 0; r < 4; ++r) CHECK(actual[c][r] == Approx(expected[c][r]).margin(margin));
}

void check_close(glm::dvec3 actual, glm::dvec3 expected, double margin) {
  INFO(Catch::StringMaker<glm::dvec3>::convert(actual) << " vs " << Catch::StringMaker<glm::dvec3>::convert(expected));
  for (glm::length_t i = 0; i < 3; ++i) CHECK(actual[i] == Approx(expected[i]).margin(margin));
}

}  // namespace

TEST_CASE("a world-space projector's matrices do not depend on the camera", "[scene][v2][matrix]") {
  const Projector p = projector_at({1, 2, 3}, {0, 0, 0}, ProjectorSpace::world);
  const glm::dmat4 look = glm::lookAt(p.eye, p.target, p.up);
  for (const Camera& camera : {camera_at({0, 0, 5}, {0, 0, 0}), camera_at({-3, 1, 2}, {4, 0, -1})}) {
    CHECK(projector_view(camera, p) == look);
    CHECK(projector_eye_in_world(camera, p) == p.eye);
  }
}

TEST_CASE("a camera-space projector: V_j = lookAt(eye_j, target_j, up_j) * V_cam", "[scene][v2][matrix]") {
  // Camera at the origin looking down +x: its eye-space +x (right) is world +z, -z is world +x.
  const Camera camera = camera_at({0, 0, 0}, {1, 0, 0});
  const Projector p = projector_at({1, 0, 0}, {1, 0, -1}, ProjectorSpace::camera);
  check_close(projector_eye_in_world(camera, p), {0, 0, 1}, 1e-15);
  check_close(projector_view(camera, p), glm::lookAt(p.eye, p.target, p.up) * camera_view(camera), 0.0);
  // The projector looks where the camera looks: world +x, from world (0, 0, 1).
  check_close(projector_view(camera, p), glm::lookAt(glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 1), glm::dvec3(0, 1, 0)), 1e-15);

  // A projector at the camera's eye looking along -z is the camera's own view.
  const Camera moved = camera_at({2, 3, 4}, {-1, 0, 0});
  const Projector headlamp = projector_at({0, 0, 0}, {0, 0, -1}, ProjectorSpace::camera);
  check_close(projector_view(moved, headlamp), camera_view(moved), 1e-15);
  check_close(projector_eye_in_world(moved, headlamp), moved.eye, 1e-14);

  // The other matrices build on V_j as for a world-space projector.
  const glm::dmat4 projection = glm::perspective(glm::radians(p.fovy_deg), p.aspect, p.near, p.far);
  check_close(projector_view_projection(camera, p), projection * projector_view(camera, p), 0.0);
  const glm::dmat4 bias = glm::scale(glm::translate(glm::dmat4(1.0), glm::dvec3(0.5)), glm::dvec3(0.5));
  check_close(projector_texture_matrix(camera, p), bias * projector_view_projection(camera, p), 0.0);
}

TEST_CASE("a camera-space projector gives a point fixed to the camera the same (s, t, r, q) in every pose", "[scene][v2][matrix]") {
  const Projector p = projector_at({0.3, -0.2, 0}, {0.1, -0.1, -5}, ProjectorSpace::camera);
  const glm::dvec4 point_in_eye_space(0.4, -0.3, -3.0, 1.0);
  const glm::dvec4 expected = projector_texture_matrix(camera_at({0, 0, 0}, {0, 0, -1}), p) * point_in_eye_space;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  for (int pose = 0; pose < 50; ++pose) {
    const Camera camera = camera_at({coordinate(random), coordinate(random), coordinate(random)},
                                    {coordinate(random), coordinate(random), coordinate(random)});
    if (std::abs(glm::normalize(camera.target - camera.eye).y) > 0.99) continue;  // up nearly parallel
    const glm::dvec4 world = glm::inverse(camera_view(camera)) * point_in_eye_space;
    const glm::dvec4 strq = projector_texture_matrix(camera, p) * world;
    for (glm::length_t i = 0; i < 4; ++i) CHECK(strq[i] == Approx(expected[i]).margin(1e-12));
  }
}

TEST_CASE("vertex_uvs: the mesh's uvs, or texgen's planes in object or eye coordinates", "[scene][v2][texgen]") {
  Object object;
  object.mesh.positions = {{0, 0, 0}, {1, 2, 3}, {-2, 0.5, 4}};
  object.mesh.uvs = {{0.25, 0.5}, {1, 1}, {0, 2}};
  object.model = glm::translate(glm::dmat4(1.0), glm::dvec3(1, 0, 0));
  const Camera camera = camera_at({0, 0, 5}, {0, 0, 0});  // eye coordinates = world - (0, 0, 5)

  CHECK(vertex_uvs(camera, object) == object.mesh.uvs);

  // object: u = 2y (a height), t left out: v = 0; M does not enter.
  object.texgen = Texgen{{0, 2, 0, 0}, {0, 0, 0, 0}, TexgenSpace::object};
  CHECK(vertex_uvs(camera, object) == std::vector<glm::dvec2>{{0, 0}, {4, 0}, {1, 0}});
  object.texgen = Texgen{{1, 0, 0, 0.5}, {0, 0, 1, -1}, TexgenSpace::object};
  CHECK(vertex_uvs(camera, object) == std::vector<glm::dvec2>{{0.5, -1}, {1.5, 2}, {-1.5, 3}});

  // eye: the planes see V_cam * M * v = v + (1, 0, -5).
  object.texgen = Texgen{{1, 0, 0, 0}, {0, 0, 1, 0.5}, TexgenSpace::eye};
  const std::vector<glm::dvec2> eye = vertex_uvs(camera, object);
  REQUIRE(eye.size() == 3);
  const std::vector<glm::dvec2> expected{{1, -4.5}, {2, -1.5}, {-1, -0.5}};
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(eye[i].x == Approx(expected[i].x).margin(1e-14));
    CHECK(eye[i].y == Approx(expected[i].y).margin(1e-14));
  }
}
