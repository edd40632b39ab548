// The example scenes under scenes/ load, with the values their files hold.
#include <filesystem>

#include <catch2/catch.hpp>

#include "catch_glm.hpp"
#include "scene/scene.hpp"
#include "source_paths.hpp"

using namespace spanlight::scene;
using spanlight::scene::test::example_scene;
using spanlight::scene::test::source_dir;

namespace {

const Texture& texture_named(const Scene& scene, const std::string& name) {
  for (const Texture& texture : scene.textures) {
    if (texture.name == name) return texture;
  }
  FAIL("no texture " << name);
  throw std::logic_error("unreachable");
}

}  // namespace

TEST_CASE("every example scene loads", "[scene]") {
  // The whole folder, so a scene added to scenes/ is covered without editing this list.
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    INFO(entry.path().filename().string());
    CHECK_NOTHROW(load_scene(entry.path()));
    ++scenes;
  }
  CHECK(scenes >= 8);  // the folder was found and read
}

TEST_CASE("slide_projector: OBJ meshes, textures and one projector as written", "[scene]") {
  const Scene scene = load_scene(example_scene("slide_projector.json"));
  CHECK(scene.name == "slide_projector");
  CHECK(scene.width == 320);
  CHECK(scene.height == 240);
  CHECK(scene.camera.eye == glm::dvec3(2.5, 2.2, 6.5));
  CHECK(scene.camera.fovy_deg == 55.0);
  CHECK(scene.ambient == glm::dvec3(0.3, 0.3, 0.32));

  REQUIRE(scene.textures.size() == 3);
  CHECK(scene.textures[0].name == "wood");  // file order is kept
  CHECK(texture_named(scene, "wood").image.width == 128);
  CHECK(texture_named(scene, "brick").image.height == 128);
  const Texture& slide = texture_named(scene, "slide");
  CHECK(slide.image.width == 256);
  CHECK(slide.image.height == 256);
  CHECK(slide.image.rgb.size() == 256u * 256u * 3u);
  CHECK(slide.wrap == Wrap::repeat);  // the default
  CHECK(slide.path.filename() == "slide.png");

  REQUIRE(scene.objects.size() == 2);
  const Object& room = scene.objects[0];
  CHECK(room.name == "room");
  CHECK(room.mesh.positions.size() == 12);
  CHECK(room.mesh.uvs.size() == 12);
  CHECK(room.mesh.triangles.size() == 6);
  CHECK(room.cull == Cull::none);
  CHECK(scene.textures[static_cast<std::size_t>(room.texture)].name == "wood");
  const Object& crate = scene.objects[1];
  CHECK(crate.mesh.positions.size() == 24);
  CHECK(crate.mesh.triangles.size() == 12);
  CHECK(crate.cull == Cull::back);

  REQUIRE(scene.projectors.size() == 1);
  const Projector& projector = scene.projectors[0];
  CHECK(projector.name == "slide");
  CHECK(projector.fovy_deg == 32.0);
  CHECK(scene.textures[static_cast<std::size_t>(projector.image)].name == "slide");
  CHECK_FALSE(projector.shadows.has_value());
}

TEST_CASE("room.obj: uvs are the file's vt values, t not flipped", "[scene]") {
  const Scene scene = load_scene(example_scene("slide_projector.json"));
  const Mesh& room = scene.objects[0].mesh;
  // room.obj's first face is "f 1/1 2/2 3/3" with vt (0,0) (4,0) (4,4).
  CHECK(room.positions[0] == glm::dvec3(-4.0, 0.0, 4.0));
  CHECK(room.uvs[0] == glm::dvec2(0.0, 0.0));
  CHECK(room.uvs[1] == glm::dvec2(4.0, 0.0));
  CHECK(room.uvs[2] == glm::dvec2(4.0, 4.0));
  CHECK(room.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});
  CHECK(room.triangles[1] == std::array<std::uint32_t, 3>{0, 2, 3});
}

TEST_CASE("horizon: inline positions, uvs and triangles as written", "[scene]") {
  const Scene scene = load_scene(example_scene("horizon.json"));
  REQUIRE(scene.objects.size() == 1);
  const Mesh& ground = scene.objects[0].mesh;
  CHECK(ground.positions.size() == 4);
  CHECK(ground.positions[2] == glm::dvec3(1000.0, 0.0, -1000.0));
  CHECK(ground.uvs[1] == glm::dvec2(200.0, 0.0));
  CHECK(ground.uvs[3] == glm::dvec2(0.0, 200.0));
  CHECK(ground.triangles.size() == 2);
  CHECK(scene.textures[0].image.width == 64);  // checker
  CHECK(scene.projectors[0].aspect == 2.0);
  CHECK(scene.camera.far == 2000.0);
}

TEST_CASE("spot_shadow: sphere mesh and a pcf2x2 shadow", "[scene]") {
  const Scene scene = load_scene(example_scene("spot_shadow.json"));
  REQUIRE(scene.objects.size() == 3);
  const Object& ball = scene.objects[2];
  CHECK(ball.name == "ball");
  // sphere.obj: 187 v, each used with its own vt, in 320 triangles.
  CHECK(ball.mesh.positions.size() == 187);
  CHECK(ball.mesh.uvs.size() == 187);
  CHECK(ball.mesh.triangles.size() == 320);
  CHECK(ball.color == glm::dvec3(0.9, 0.85, 0.7));
  CHECK(ball.texture == -1);
  CHECK(texture_named(scene, "checker").filter == Filter::nearest);

  REQUIRE(scene.projectors.size() == 1);
  REQUIRE(scene.projectors[0].shadows.has_value());
  const Shadows& shadows = *scene.projectors[0].shadows;
  CHECK(shadows.map_size == 256);
  CHECK(shadows.bias == 0.002);
  CHECK(shadows.filter == ShadowFilter::pcf2x2);
  CHECK(scene.projectors[0].color == glm::dvec3(1.0, 0.95, 0.85));
}

TEST_CASE("three_projectors: colours above 1 and mixed shadows", "[scene]") {
  const Scene scene = load_scene(example_scene("three_projectors.json"));
  REQUIRE(scene.projectors.size() == 3);
  const Projector& red = scene.projectors[0];
  CHECK(red.color == glm::dvec3(1.6, 0.2, 0.2));
  CHECK(red.aspect == 1.0);  // the default
  REQUIRE(red.shadows.has_value());
  CHECK(red.shadows->map_size == 128);
  CHECK(red.shadows->filter == ShadowFilter::nearest);
  CHECK(scene.projectors[2].aspect == 1.3);
  CHECK_FALSE(scene.projectors[2].shadows.has_value());
  CHECK(scene.objects[1].model[3] == glm::dvec4(0.0, 1.0, -1.0, 1.0));  // translate only
}
