// Scene format version 2 (docs/scene-format.md): its fields load with the values and
// defaults the spec gives, and a version-1 file may hold none of them. The malformed
// version-2 scenes are in bad/ (test_bad_scenes.cpp).
#include <string>

#include <catch2/catch.hpp>

#include "catch_glm.hpp"
#include "scene/scene.hpp"
#include "scratch_folder.hpp"
#include "source_paths.hpp"

using namespace spanlight::scene;
using spanlight::scene::test::ScratchFolder;
using spanlight::scene::test::source_dir;

namespace {

std::string asset(const char* relative) { return (source_dir() / "scenes" / "assets" / relative).string(); }

// A scene of the given version with the given textures, objects and projectors (JSON text).
std::string scene_text(int version, const std::string& textures, const std::string& objects,
                       const std::string& projectors) {
  return R"({
  "spanlight_scene": )" + std::to_string(version) + R"(,
  "output": { "width": 64, "height": 48 },
  "camera": { "eye": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 60, "near": 0.1, "far": 10 },
  "textures": { )" + textures + R"( },
  "objects": [ )" + objects + R"( ],
  "projectors": [ )" + projectors + R"( ]
})";
}

const std::string checker = R"("checker": { "image": ")" + asset("textures/checker.png") + R"(" })";
const std::string triangle = R"({ "positions": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]], "triangles": [[0, 1, 2]] })";
const std::string projector =
    R"({ "eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 40, "near": 0.5, "far": 10, "image": "checker" })";

Scene load_text(const ScratchFolder& folder, const std::string& text) { return load_scene(folder.write("s.json", text)); }

}  // namespace

TEST_CASE("version 2: every new field loads as written", "[scene][v2]") {
  const ScratchFolder folder;
  const std::string textures = checker + R"(,
    "mip": { "image": ")" + asset("textures/wood.png") + R"(", "filter": "trilinear" })";
  const std::string objects = R"({ "positions": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]], "triangles": [[0, 1, 2]],
      "texture": "mip", "texgen": { "s": [1, 2, 3, 4], "t": [-1, 0.5, 0, 0.25], "space": "eye" } })";
  const std::string projectors =
      R"({ "eye": [0.5, 0, 0], "target": [0, 0, -5], "up": [0, 1, 0], "fovy_deg": 40, "near": 0.5, "far": 10,
           "image": "checker", "falloff": "checker", "facing_only": true, "space": "camera" })";
  const Scene scene = load_text(folder, scene_text(2, textures, objects, projectors));

  CHECK(scene.version == 2);
  CHECK(scene.textures[1].filter == Filter::trilinear);
  const Object& object = scene.objects[0];
  REQUIRE(object.texgen.has_value());
  CHECK(object.texgen->s == glm::dvec4(1, 2, 3, 4));
  CHECK(object.texgen->t == glm::dvec4(-1, 0.5, 0, 0.25));
  CHECK(object.texgen->space == TexgenSpace::eye);
  const Projector& p = scene.projectors[0];
  CHECK(p.falloff == 0);  // the texture "checker"
  CHECK(p.facing_only);
  CHECK(p.space == ProjectorSpace::camera);
  CHECK(p.eye == glm::dvec3(0.5, 0, 0));  // as given: in the camera's eye space
}

TEST_CASE("version 2: left-out fields take the spec's defaults", "[scene][v2]") {
  const ScratchFolder folder;
  const std::string objects = R"({ "positions": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]], "triangles": [[0, 1, 2]],
      "texgen": { "s": [0, 2, 0, 0] } })";
  const Scene scene = load_text(folder, scene_text(2, checker, objects + ", " + triangle, projector));
  REQUIRE(scene.objects[0].texgen.has_value());
  CHECK(scene.objects[0].texgen->t == glm::dvec4(0.0));  // t defaults to [0, 0, 0, 0]
  CHECK(scene.objects[0].texgen->space == TexgenSpace::object);
  CHECK_FALSE(scene.objects[1].texgen.has_value());
  const Projector& p = scene.projectors[0];
  CHECK(p.falloff == -1);
  CHECK_FALSE(p.facing_only);
  CHECK(p.space == ProjectorSpace::world);
}

TEST_CASE("version 1 files still load, as version 1", "[scene][v2]") {
  const ScratchFolder folder;
  const Scene scene = load_text(folder, scene_text(1, checker, triangle, projector));
  CHECK(scene.version == 1);
  CHECK_FALSE(scene.objects[0].texgen.has_value());
  CHECK(scene.projectors[0].falloff == -1);
}

TEST_CASE("a version-2 field in a version-1 file is refused as new in version 2", "[scene][v2]") {
  const ScratchFolder folder;
  struct Case {
    std::string textures, objects, projectors, field;
  };
  const std::string trilinear = R"("checker": { "image": ")" + asset("textures/checker.png") + R"(", "filter": "trilinear" })";
  const std::string texgen = R"({ "positions": [[-1, -1, 0], [1, -1, 0], [0, 1, 0]], "triangles": [[0, 1, 2]],
      "texgen": { "s": [1, 0, 0, 0] } })";
  const auto with = [](const std::string& extra) {
    return R"({ "eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 40, "near": 0.5, "far": 10,
      "image": "checker", )" + extra + " }";
  };
  for (const Case& c : {Case{trilinear, triangle, projector, "textures.checker.filter"},
                        Case{checker, texgen, projector, "objects[0].texgen"},
                        Case{checker, triangle, with(R"("falloff": "checker")"), "projectors[0].falloff"},
                        Case{checker, triangle, with(R"("facing_only": false)"), "projectors[0].facing_only"},
                        Case{checker, triangle, with(R"("space": "world")"), "projectors[0].space"}}) {
    INFO(c.field);
    try {
      load_text(folder, scene_text(1, c.textures, c.objects, c.projectors));
      FAIL("loaded");
    } catch (const SceneError& error) {
      CHECK(error.field() == c.field);
      CHECK_THAT(error.expected(), Catch::StartsWith("expected ") && Catch::Contains("new in version 2"));
    }
    // The same scene as version 2 loads.
    CHECK_NOTHROW(load_text(folder, scene_text(2, c.textures, c.objects, c.projectors)));
  }
}

TEST_CASE("trilinear takes power-of-two sizes, square or not", "[scene][v2]") {
  const ScratchFolder folder;
  const std::string ramp = R"("ramp": { "image": ")" + (source_dir() / "scenes" / "assets" / "textures" / "falloff.png").string() +
                           R"(", "filter": "trilinear", "wrap": "clamp" })";
  const Scene scene = load_text(folder, scene_text(2, checker + ", " + ramp, triangle, projector));
  CHECK(scene.textures[1].image.width == 64);  // 64 x 1
  CHECK(scene.textures[1].image.height == 1);
  CHECK(scene.textures[1].filter == Filter::trilinear);
}

TEST_CASE("texgen overrides an OBJ's vt: the mesh loads with its vt and the planes", "[scene][v2]") {
  const ScratchFolder folder;
  const std::string objects = R"({ "mesh": ")" + asset("meshes/plane.obj") + R"(", "texture": "checker",
      "texgen": { "s": [1, 0, 0, 0] } })";
  const Scene scene = load_text(folder, scene_text(2, checker, objects, projector));
  CHECK(scene.objects[0].mesh.uvs.size() == scene.objects[0].mesh.positions.size());
  CHECK(scene.objects[0].texgen->s == glm::dvec4(1, 0, 0, 0));  // vertex_uvs uses these (test_matrices.cpp)
}

TEST_CASE("an unknown filter is told the choices of the file's version", "[scene][v2]") {
  const ScratchFolder folder;
  for (const int version : {1, 2}) {
    const std::string mipmap = R"("checker": { "image": ")" + asset("textures/checker.png") + R"(", "filter": "mipmap" })";
    try {
      load_text(folder, scene_text(version, mipmap, triangle, projector));
      FAIL("loaded");
    } catch (const SceneError& error) {
      CHECK(error.field() == "textures.checker.filter");
      CHECK_THAT(error.expected(), Catch::StartsWith(version == 1 ? "expected one of nearest, bilinear, got"
                                                                  : "expected one of nearest, bilinear, trilinear, got"));
    }
  }
}
