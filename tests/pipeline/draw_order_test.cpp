// Draw order (5_frame/draw.hpp): an object drawn without culling draws the
// triangles that face the view first and the others after them, so the back of
// a closed model is hidden before it is shaded. The picture is still the
// nearest surface: the same as with back faces culled, wherever that one has a
// surface. The sphere is a closed solid, which draw_pass would draw with its
// back faces culled (closed_solid_test.cpp); here it is marked open, so both
// sides are drawn.
#include <catch2/catch.hpp>

#include <cstdint>
#include <vector>

#include "pipeline_support.hpp"
#include "sphere_scene.hpp"

using namespace spanlight;
using namespace spanlight::ptest;

TEST_CASE("a closed model drawn without culling shades each pixel once and shows the culled picture", "[pipeline][order]") {
  const auto open = prepare::prepare_scene(sphere_scene(scene::Cull::none));
  open->objects[0].closed = false;
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
