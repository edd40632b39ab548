// Draw order (5_frame/draw.hpp): an object drawn without culling draws the
// triangles that face the view first and the others after them, so the back of
// a closed model is hidden before it is shaded. The picture is still the
// nearest surface: the same as with back faces culled, wherever that one has a
// surface.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "pipeline_support.hpp"

using namespace spanlight;
using namespace spanlight::ptest;

namespace {

// A closed UV sphere of radius 1 at the origin, counter-clockwise seen from outside, its
// triangles ring by ring and around each ring, so front and back faces alternate in the
// file. uv wraps once around and once pole to pole (a repeating texture).
scene::Object sphere(int rings, int segments, scene::Cull cull) {
  scene::Object object;
  object.name = "sphere";
  object.cull = cull;
  object.texture = 0;
  for (int r = 0; r <= rings; ++r) {
    const double polar = std::numbers::pi * r / rings;
    for (int s = 0; s <= segments; ++s) {  // the seam's column twice, with u = 0 and u = 1
      const double around = 2.0 * std::numbers::pi * s / segments;
      object.mesh.positions.emplace_back(std::sin(polar) * std::cos(around), std::cos(polar), -std::sin(polar) * std::sin(around));
      object.mesh.uvs.emplace_back(static_cast<double>(s) / segments, 1.0 - static_cast<double>(r) / rings);
    }
  }
  const auto at = [segments](int r, int s) { return static_cast<std::uint32_t>(r * (segments + 1) + s); };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      // Seen from outside, with y up and the ring running towards -z from +x: (r, s), (r + 1, s),
      // (r + 1, s + 1) is counter-clockwise. The poles' degenerate halves are left out.
      if (r + 1 < rings) object.mesh.triangles.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
      if (r > 0) object.mesh.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
    }
  return object;
}

scene::Scene sphere_scene(scene::Cull cull) {
  auto s = empty_scene(160, 120, {0.3, 0.5, 3.5}, {0, 0, 0}, {0, 1, 0}, 45.0, 0.5, 10.0);
  s.ambient = glm::dvec3(1.0);
  scene::Image stripes = solid_image(16, 16, {40, 90, 200});
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; x += 2)
      for (int c = 0; c < 3; ++c) stripes.rgb[static_cast<std::size_t>((y * 16 + x) * 3 + c)] = 230;
  s.textures.push_back(texture("stripes", stripes, scene::Filter::bilinear, scene::Wrap::repeat));
  s.objects.push_back(sphere(16, 32, cull));
  return s;
}

}  // namespace

TEST_CASE("a closed model drawn without culling shades each pixel once and shows the culled picture", "[pipeline][order]") {
  const auto open = prepare::prepare_scene(sphere_scene(scene::Cull::none));
  const auto culled = prepare::prepare_scene(sphere_scene(scene::Cull::back));
  for (const std::uint8_t depth_bits : {std::uint8_t{24}, std::uint8_t{16}}) {
    INFO("depth bits " << int{depth_bits});
    const ObservedFrame none = render_observed(*open, knobs_with(Passes::fused, depth_bits, PixelFormat::rgb565));
    const ObservedFrame back = render_observed(*culled, knobs_with(Passes::fused, depth_bits, PixelFormat::rgb565));

    // Each pixel is shaded once: a back face behind the front ones fails the depth test.
    std::vector<int> shaded(none.depth.size(), 0);
    for (const PassEvent& e : none.log.events) ++shaded[e.index];
    int shaded_twice = 0, covered = 0;
    for (const int n : shaded) {
      shaded_twice += n > 1;
      covered += n > 0;
    }
    CHECK(shaded_twice == 0);
    CHECK(covered > 4000);  // the sphere fills about a third of the 160 x 120 frame

    // Where the culled sphere has a surface, both frames hold the same depth and colour. A back
    // face may still cover a silhouette pixel whose centre lies exactly on the front's edge (the
    // other side of the tie rule), where the culled frame shows the background.
    const std::uint32_t clear = depth_clear(depth_bits);
    int differ = 0, culled_covers = 0;
    for (std::size_t i = 0; i < none.depth.size(); ++i) {
      if (back.depth[i] == clear) continue;
      ++culled_covers;
      differ += none.depth[i] != back.depth[i] || none.rgb[3 * i] != back.rgb[3 * i] ||
                none.rgb[3 * i + 1] != back.rgb[3 * i + 1] || none.rgb[3 * i + 2] != back.rgb[3 * i + 2];
    }
    CHECK(differ == 0);
    CHECK(culled_covers <= covered);
  }
}
