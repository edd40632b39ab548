// Bands: a frame drawn in bands of N rows into buffers of N rows, each band handed to
// Hooks::band_done, gives the whole frame's bytes, for every N from 1 to the frame's
// height, with the fused pass and the multipass: two small scenes, and the live demo
// at its full 320x240 at its first frame's run-time pose.
#include <catch2/catch.hpp>

#include "live_support.hpp"

namespace {

using namespace spanlight;

void require_every_band_height(const PreparedScene& scene, const FrameMatrices& matrices, Knobs knobs) {
  for (const Passes passes : {Passes::fused, Passes::multipass}) {
    knobs.passes = passes;
    INFO((passes == Passes::fused ? "fused" : "multipass"));
    const std::vector<std::uint8_t> whole = live_test::render_in_bands(scene, matrices, knobs, 0);
    REQUIRE(!whole.empty());
    for (std::uint16_t rows = 1; rows <= scene.height; ++rows) {
      INFO("band rows " << rows);
      REQUIRE(live_test::render_in_bands(scene, matrices, knobs, rows) == whole);
    }
  }
}

}  // namespace

TEST_CASE("bands: every band height gives the whole frame, small scenes") {
  for (const char* file : {"spot_shadow.json", "three_projectors.json"}) {
    INFO(file);
    const live_test::Loaded l = live_test::load(file, nullptr, 48, 36);
    require_every_band_height(l.prepared->scene, l.prepared->matrices, Knobs{});
  }
}

TEST_CASE("bands: every band height gives the whole frame, the live demo at full size") {
  const live_test::Loaded l = live_test::load("live_spotlight.json", "live_spotlight.json");
  prepare::PosedMatrices matrices(l.prepared->scene);
  REQUIRE(prepare::pose_frame(l.prepared->scene, l.prepared_animation->animation, 0, matrices).ok());
  Knobs knobs;
  knobs.format = PixelFormat::rgb565;
  knobs.depth_bits = 16;
  require_every_band_height(l.prepared->scene, matrices.storage().matrices(), knobs);
}
