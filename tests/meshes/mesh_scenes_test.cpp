// The mesh scenes are what issue 19 asks of a shared mesh scene: a textured model
// of at least 2,000 triangles, drawn without culling, covering 25-50 % of its
// 320x240 frame in the float model, with triangles of a few to a few tens of
// pixels. The triangle count is the loaded scene's, so it follows the files.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include "float_model/float_model.hpp"
#include "scene/scene.hpp"
#include "source_tree.hpp"

namespace fm = spanlight::float_model;
namespace scene = spanlight::scene;
using spanlight::mesh_generator::test::all_mesh_scene_files;
using spanlight::mesh_generator::test::mesh_scene_files;
using spanlight::mesh_generator::test::scenes_folder;

namespace {

std::size_t triangle_count(const scene::Scene& s) {
  std::size_t triangles = 0;
  for (const scene::Object& object : s.objects) triangles += object.mesh.triangles.size();
  return triangles;
}

// Screen areas in pixels of the triangles with every vertex in front of the camera.
std::vector<double> screen_areas(const scene::Scene& s) {
  const glm::dmat4 view_projection = scene::camera_view_projection(s);
  std::vector<double> areas;
  for (const scene::Object& object : s.objects) {
    const glm::dmat4 to_clip = view_projection * object.model;
    for (const auto& triangle : object.mesh.triangles) {
      glm::dvec2 window[3];
      bool in_front = true;
      for (int k = 0; k < 3; ++k) {
        const glm::dvec4 clip = to_clip * glm::dvec4(object.mesh.positions[triangle[static_cast<std::size_t>(k)]], 1.0);
        in_front = in_front && clip.w > 0.0;
        window[k] = {(clip.x / clip.w + 1.0) * s.width / 2.0, (clip.y / clip.w + 1.0) * s.height / 2.0};
      }
      const glm::dvec2 a = window[1] - window[0], b = window[2] - window[0];
      if (in_front) areas.push_back(std::abs(a.x * b.y - a.y * b.x) / 2.0);
    }
  }
  return areas;
}

}  // namespace

TEST_CASE("there are mesh scenes: one shared in scenes/ and checks in scenes/checks/", "[meshes]") {
  CHECK_FALSE(mesh_scene_files(scenes_folder()).empty());
  CHECK(mesh_scene_files(scenes_folder() / "checks").size() >= 2);
}

TEST_CASE("every mesh scene draws at least 2,000 triangles without culling on 25-50 % of a 320x240 frame", "[meshes]") {
  for (const auto& file : all_mesh_scene_files()) {
    INFO(file.string());
    const scene::Scene s = scene::load_scene(file);
    CHECK(s.width == 320);
    CHECK(s.height == 240);
    CHECK(triangle_count(s) >= 2000);
    for (const scene::Object& object : s.objects) CHECK(object.cull == scene::Cull::none);

    const fm::FloatFrame frame = fm::render_float(s);
    const auto covered = static_cast<double>(std::count_if(frame.object.begin(), frame.object.end(), [](int o) { return o >= 0; }));
    const double fraction = covered / static_cast<double>(frame.object.size());
    INFO("covered " << covered << " pixels of " << frame.object.size() << " (" << 100.0 * fraction << " %), "
                    << triangle_count(s) << " triangles");
    CHECK(fraction >= 0.25);
    CHECK(fraction <= 0.50);
  }
}

TEST_CASE("a mesh scene's triangles are small, as a real model's: median screen area 2 to 50 pixels", "[meshes]") {
  for (const auto& file : all_mesh_scene_files()) {
    INFO(file.string());
    std::vector<double> areas = screen_areas(scene::load_scene(file));
    REQUIRE(!areas.empty());
    std::sort(areas.begin(), areas.end());
    const auto percentile = [&](std::size_t p) { return areas[(areas.size() - 1) * p / 100]; };
    const double median = percentile(50);
    INFO("triangle areas: median " << median << " px, 10th percentile " << percentile(10) << ", 90th " << percentile(90)
                                   << ", largest " << areas.back() << "; "
                                   << std::count_if(areas.begin(), areas.end(), [](double a) { return a < 1.0; })
                                   << " below 1 px");
    CHECK(median >= 2.0);
    CHECK(median <= 50.0);
  }
}
