// Whole-object rejection (vertex_cache.hpp, object_beyond_a_plane): an object whose bounding
// box lies beyond one clip plane starts no triangle and changes no byte, and an object that
// only crosses a plane is still drawn.
#include <catch2/catch.hpp>

#include <string>

#include "pipeline_support.hpp"

using namespace spanlight;
using namespace spanlight::ptest;

namespace {

// A grid of n x n quads (more than 8 vertices, so the box test is worth its eight transforms)
// in the plane z = z0, spanning [x0, x0 + size] x [y0, y0 + size].
scene::Object grid(std::string name, double x0, double y0, double z0, double size, int n) {
  scene::Object object;
  object.name = std::move(name);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) object.mesh.positions.emplace_back(x0 + size * i / n, y0 + size * j / n, z0);
  object.mesh.uvs.assign(object.mesh.positions.size(), glm::dvec2(0.0));
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      object.mesh.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      object.mesh.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return object;
}

// The camera at z = 5 looks down -z; a wall at z = 0 fills the view.
scene::Scene wall_scene() {
  auto s = empty_scene(64, 48, {0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60.0, 0.5, 50.0);
  s.ambient = glm::dvec3(1.0);
  s.objects.push_back(grid("wall", -8, -8, 0, 16, 2));
  return s;
}

struct TriangleCount : NoHooks {
  long* started;
  void triangle_begin() { ++*started; }
};

struct Drawn {
  long triangles_started = 0;
  std::vector<std::uint8_t> rgb;
};

Drawn draw(const scene::Scene& s, Passes passes) {
  Drawn d;
  const auto prepared = prepare::prepare_scene(s);
  TriangleCount hooks{};
  hooks.started = &d.triangles_started;
  d.rgb = prepare::render_fixed_with_hooks(*prepared, knobs_with(passes), hooks).rgb;
  return d;
}

}  // namespace

TEST_CASE("an object beyond one clip plane starts no triangle and changes no byte", "[pipeline][rejection]") {
  for (const Passes passes : {Passes::fused, Passes::multipass}) {
    const Drawn alone = draw(wall_scene(), passes);
    const long passes_drawn = passes == Passes::fused ? 1 : 2;  // depth + ambient, modulate (no projector)
    REQUIRE(alone.triangles_started == 8 * passes_drawn);

    struct Case {
      const char* where;
      scene::Object object;
    };
    const Case beyond[] = {
        {"behind the camera", grid("behind", -1, -1, 7, 2, 4)},
        {"beyond the far plane", grid("far", -1, -1, -60, 2, 4)},
        {"far beyond the left guard band", grid("left", -400, -1, -1, 2, 4)},
    };
    for (const Case& c : beyond) {
      INFO(c.where << (passes == Passes::fused ? ", fused" : ", multipass"));
      scene::Scene s = wall_scene();
      s.objects.push_back(c.object);
      const Drawn with = draw(s, passes);
      CHECK(with.triangles_started == alone.triangles_started);
      CHECK(with.rgb == alone.rgb);
    }

    // Control: a red grid 1 unit in front of the camera (the near plane is at z = 4.5) with one
    // vertex moved behind the camera, so its box spans the near plane: it is drawn.
    scene::Scene crossing = wall_scene();
    crossing.objects.push_back(grid("crossing", -1, -1, 4.0, 2, 4));
    crossing.objects.back().mesh.positions[0].z = 6.0;
    crossing.objects.back().color = glm::dvec3(1.0, 0.0, 0.0);
    const Drawn straddling = draw(crossing, passes);
    CHECK(straddling.triangles_started == alone.triangles_started + 32 * passes_drawn);
    CHECK(straddling.rgb != alone.rgb);
  }
}
