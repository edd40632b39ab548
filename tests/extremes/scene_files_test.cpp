// The scene files of scenes/extremes/: the extreme cases as files anyone can
// render with the CLI (`spanlight render scenes/extremes/NAME.json ...`), and
// the reported bugs' reproductions. Each must load (they are valid scenes)
// and then behave as stated here; the in-memory tests beside this file hold
// the detailed derivations.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "extremes_support.hpp"

using namespace spanlight::xt;

namespace {

sc::Scene load(const std::string& name) {
  return sc::load_scene(std::filesystem::path(SPANLIGHT_SOURCE_DIR) / "scenes" / "extremes" / (name + ".json"));
}

void check_file(const std::string& name, int radius, int tolerance, double min_psnr) {
  const sc::Scene s = load(name);
  const Both b = render_both(s);
  dump(b, "file_" + name);
  const Agreement a = agree(b, radius, tolerance);
  INFO(name << ": " << describe(a, s.width));
  CHECK(a.covered_ref > s.width * s.height / 4);
  CHECK(a.unexplained == 0);
  CHECK(a.stats.psnr_db >= min_psnr);
}

}  // namespace

TEST_CASE("scenes/extremes: the agreeing cases", "[extremes][files]") {
  // Tolerances as derived in the in-memory tests: 3 levels for flat colours
  // (near_plane_test.cpp); 29 for the 170-degree bilinear projector
  // (projector_test.cpp); the 10 km floor's 1e4 texture repeats alias toward
  // the horizon in both renderers, so only coverage is held to the outline
  // rule there (tolerance 255) and the PSNR bound carries the colour.
  check_file("near_plane_cut", 1, 3, 40.0);
  check_file("wide_projector_room", 1, 29, 35.0);
  check_file("ten_km_floor", 1, 255, 30.0);
}

TEST_CASE("scenes/extremes/last_depth_step.json: a surface in the last 24-bit depth step is drawn",
          "[extremes][files]") {
  // The depth_store regression (depth_test.cpp): the float model draws the square, so must the pipeline.
  const sc::Scene s = load("last_depth_step");
  const Both b = render_both(s);
  const Agreement a = agree(b, 1, 3);
  INFO(describe(a, s.width));
  CHECK(a.covered_ref > 500);
  CHECK(a.covered_fixed == a.covered_ref);
}

TEST_CASE("scenes/extremes/guard_band_overflow.json: w near the transform's bound", "[extremes][files]") {
  // The clip.hpp guard-band overflow regression (huge_test.cpp).
  const sc::Scene s = load("guard_band_overflow");
  REQUIRE_NOTHROW(pr::prepare_scene(s));
  const Both b = render_both(s);
  const Agreement a = agree(b, 1, 3);
  INFO(describe(a, s.width));
  CHECK(a.covered_ref > 60);
  CHECK(a.unexplained == 0);
}

TEST_CASE("scenes/extremes/uv_beyond_2_29.json: texel coordinates beyond 2^29 are refused", "[extremes][files]") {
  // The uv range check in prepare (huge_test.cpp); drawn, it would overflow int32 in 2_triangle/attributes.hpp.
  CHECK_THROWS_AS(pr::prepare_scene(load("uv_beyond_2_29")), pr::PrepareError);
}

TEST_CASE("scenes/extremes/bright_projector.json: light within 3 levels under a colour-16 projector",
          "[extremes][files]") {
  // The projector texel is not rounded to 8 bits before the colour multiplies it (colour_test.cpp).
  const sc::Scene s = load("bright_projector");
  const Both b = render_both(s);
  const Agreement a = agree(b, 0, 3);
  INFO(describe(a, s.width));
  CHECK(a.stats.max_abs_lsb <= 3);
}
