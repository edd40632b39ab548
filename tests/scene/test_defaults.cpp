// Fields the spec gives defaults to may be left out.
#include <catch2/catch.hpp>

#include "catch_glm.hpp"
#include "scene/scene.hpp"
#include "scratch_folder.hpp"
#include "source_paths.hpp"

using namespace spanlight::scene;
using spanlight::scene::test::ScratchFolder;
using spanlight::scene::test::source_dir;

namespace {

// The least a scene may say: one texture, one inline triangle, one projector.
std::string minimal_scene(const std::string& checker_png) {
  return R"({
  "spanlight_scene": 1,
  "output": { "width": 64.0, "height": 48 },
  "camera": { "eye": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 60, "near": 0.1, "far": 10 },
  "textures": { "checker": { "image": ")" + checker_png + R"(" } },
  "objects": [ { "positions": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]], "triangles": [[0, 1, 2]] } ],
  "projectors": [ { "eye": [0, 2, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 40, "near": 0.5, "far": 10,
                    "image": "checker", "shadows": { "map_size": 64, "bias": 0 } } ]
})";
}

}  // namespace

TEST_CASE("left-out fields take the spec's defaults", "[scene]") {
  const ScratchFolder folder;
  const auto checker = source_dir() / "scenes" / "assets" / "textures" / "checker.png";
  const Scene scene = load_scene(folder.write("my_minimal_scene.json", minimal_scene(checker.string())));

  CHECK(scene.name == "my_minimal_scene");  // the file name without extension
  CHECK(scene.width == 64);                  // 64.0 is an integer too
  CHECK(scene.ambient == glm::dvec3(0.0));

  REQUIRE(scene.textures.size() == 1);
  CHECK(scene.textures[0].filter == Filter::bilinear);
  CHECK(scene.textures[0].wrap == Wrap::repeat);

  REQUIRE(scene.objects.size() == 1);
  const Object& object = scene.objects[0];
  CHECK(object.name == "objects[0]");
  CHECK(object.color == glm::dvec3(1.0));
  CHECK(object.texture == -1);
  CHECK(object.cull == Cull::none);
  CHECK(object.model == glm::dmat4(1.0));
  REQUIRE(object.mesh.uvs.size() == 3);
  CHECK(object.mesh.uvs[2] == glm::dvec2(0.0));

  REQUIRE(scene.projectors.size() == 1);
  const Projector& projector = scene.projectors[0];
  CHECK(projector.name == "projectors[0]");
  CHECK(projector.aspect == 1.0);
  CHECK(projector.color == glm::dvec3(1.0));
  CHECK(projector.image == 0);
  REQUIRE(projector.shadows.has_value());
  CHECK(projector.shadows->filter == ShadowFilter::nearest);
  CHECK(projector.shadows->bias == 0.0);
}

TEST_CASE("textures, objects and projectors may be left out", "[scene]") {
  const ScratchFolder folder;
  const Scene scene = load_scene(folder.write("empty.json", R"({
    "spanlight_scene": 1, "output": { "width": 1, "height": 4096 },
    "camera": { "eye": [0, 0, 0], "target": [0, 0, -1], "up": [0, 1, 0], "fovy_deg": 179.9, "near": 1e-6, "far": 1e-5 } })"));
  CHECK(scene.textures.empty());
  CHECK(scene.objects.empty());
  CHECK(scene.projectors.empty());
  CHECK(scene.height == 4096);
}

TEST_CASE("relative paths are relative to the scene file's folder, not the working directory", "[scene]") {
  const ScratchFolder folder;
  std::filesystem::create_directory(folder.path() / "meshes");
  folder.write("meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const Scene scene = load_scene(folder.write("scene.json", R"({
    "spanlight_scene": 1, "output": { "width": 8, "height": 8 },
    "camera": { "eye": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 60, "near": 0.1, "far": 10 },
    "objects": [ { "mesh": "meshes/tri.obj" } ] })"));
  REQUIRE(scene.objects.size() == 1);
  CHECK(scene.objects[0].mesh.triangles.size() == 1);
}
