// OBJ files: polygons fan-triangulated in file order, one Mesh vertex per
// distinct (v, vt) pair, uv 0 where a corner has no vt.
#include <catch2/catch.hpp>

#include "catch_glm.hpp"
#include "scene/scene.hpp"
#include "scratch_folder.hpp"

using namespace spanlight::scene;
using spanlight::scene::test::ScratchFolder;

namespace {

using Triangle = std::array<std::uint32_t, 3>;

// Loads obj_text through a one-object scene, the only way in.
Mesh load_obj(const std::string& obj_text) {
  const ScratchFolder folder;
  folder.write("mesh.obj", obj_text);
  const auto scene_file = folder.write("scene.json", R"({
    "spanlight_scene": 1, "output": { "width": 8, "height": 8 },
    "camera": { "eye": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 60, "near": 0.1, "far": 10 },
    "objects": [ { "mesh": "mesh.obj" } ] })");
  return load_scene(scene_file).objects.at(0).mesh;
}

}  // namespace

TEST_CASE("a polygon is fanned from its first corner in file order", "[scene][obj]") {
  const Mesh mesh = load_obj(
      "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 1\nvt 0 1\n"
      "f 1/1 2/2 3/3 4/4 5/5\n");
  REQUIRE(mesh.triangles.size() == 3);
  CHECK(mesh.triangles[0] == Triangle{0, 1, 2});
  CHECK(mesh.triangles[1] == Triangle{0, 2, 3});
  CHECK(mesh.triangles[2] == Triangle{0, 3, 4});
  REQUIRE(mesh.positions.size() == 5);
  CHECK(mesh.positions[3] == glm::dvec3(1.0, 2.0, 0.0));
  CHECK(mesh.uvs[3] == glm::dvec2(0.5, 1.0));
}

TEST_CASE("one position used with two vt becomes two vertices", "[scene][obj]") {
  // v 1 is corner 1 of both triangles, with vt 1 in the first and vt 4 in the second.
  const Mesh mesh = load_obj(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 2\n"
      "f 1/1 2/2 3/3\nf 1/4 3/3 4/2\n");
  REQUIRE(mesh.positions.size() == 5);  // (1,1) (2,2) (3,3) (1,4) (4,2)
  CHECK(mesh.triangles[0] == Triangle{0, 1, 2});
  CHECK(mesh.triangles[1] == Triangle{3, 2, 4});  // (3,3) is shared, not duplicated
  CHECK(mesh.positions[3] == mesh.positions[0]);
  CHECK(mesh.uvs[0] == glm::dvec2(0.0, 0.0));
  CHECK(mesh.uvs[3] == glm::dvec2(0.5, 2.0));
}

TEST_CASE("corners without vt get uv 0", "[scene][obj]") {
  const Mesh mesh = load_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  REQUIRE(mesh.positions.size() == 4);
  REQUIRE(mesh.uvs.size() == 4);
  for (const glm::dvec2& uv : mesh.uvs) CHECK(uv == glm::dvec2(0.0));
  CHECK(mesh.triangles.size() == 2);
}

TEST_CASE("normals are ignored and negative indices count back from the last v", "[scene][obj]") {
  const Mesh mesh = load_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0.5 0.5\n"
      "f -3/-1/1 -2/-1/1 -1/-1/1\n");
  REQUIRE(mesh.positions.size() == 3);
  CHECK(mesh.positions[2] == glm::dvec3(0.0, 1.0, 0.0));
  CHECK(mesh.uvs[1] == glm::dvec2(0.5, 0.5));
  CHECK(mesh.triangles[0] == Triangle{0, 1, 2});
}

TEST_CASE("OBJ coordinates are read in double, not rounded to float", "[scene][obj]") {
  const Mesh mesh = load_obj("v 0.1 0.2 0.3\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  // tinyobjloader sums digit * 10^-k, so it may miss the nearest double by
  // an ulp or so; float would be off by ~1e-8.
  CHECK(mesh.positions[0].x == Approx(0.1).margin(1e-15).epsilon(0));
  CHECK(mesh.positions[0].y == Approx(0.2).margin(1e-15).epsilon(0));
  CHECK(mesh.positions[0].z == Approx(0.3).margin(1e-15).epsilon(0));
}
