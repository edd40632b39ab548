// `analyze` picks formats from measured ranges: scenes built to need more range
// than the default formats hold get those formats rejected and a larger one
// chosen; an ordinary scene keeps the most precise one.
#include <filesystem>
#include <string>

#include <catch2/catch.hpp>

#include "analyze/format_choice.hpp"
#include "analyze/scene_ranges.hpp"
#include "prepare/prepare.hpp"
#include "scene/scene.hpp"
#include "sweep/coordinate_map.hpp"

using namespace spanlight;

namespace {

std::filesystem::path scene_file(const std::string& name) {
  return std::filesystem::path(SPANLIGHT_SOURCE_DIR) / "tests" / "sweep" / "scenes" / (name + ".json");
}

const analyze::FormatChoice& choice_named(const std::vector<analyze::FormatChoice>& choices, const std::string& prefix) {
  for (const analyze::FormatChoice& c : choices)
    if (c.quantity.rfind(prefix, 0) == 0) return c;
  FAIL("no format choice for " << prefix);
  return choices.front();
}

std::string chosen(const analyze::FormatChoice& c) { return c.chosen ? c.candidates[*c.chosen].format : "none"; }

bool rejected(const analyze::FormatChoice& c, const std::string& format) {
  for (const analyze::Candidate& k : c.candidates)
    if (k.format == format) return !k.holds;
  FAIL("no candidate " << format);
  return false;
}

}  // namespace

TEST_CASE("uv x size of 64000 texels overflows Q15.16: Q19.12 is chosen", "[analyze]") {
  const scene::Scene s = scene::load_scene(scene_file("wide_uv"));
  const analyze::SceneRanges ranges = analyze::measure_ranges(s);
  REQUIRE(ranges.objects.size() == 1);
  CHECK(ranges.objects[0].largest_texel == 64000.0);
  const std::vector<analyze::FormatChoice> choices = analyze::choose_formats(ranges);
  const analyze::FormatChoice& uv = choice_named(choices, "uv x texture size of floor");
  CHECK(rejected(uv, "Q15.16"));
  CHECK_FALSE(rejected(uv, "Q19.12"));
  CHECK(chosen(uv) == "Q19.12");
  // prepare's own choice never keeps more fraction bits than the chosen format allows.
  CHECK(prepare::uv_frac_bits_for(ranges.objects[0].largest_texel) >= 12);
  CHECK(analyze::uv_limit(prepare::uv_frac_bits_for(ranges.objects[0].largest_texel)) > 64000.0);
}

TEST_CASE("uv x size of 1.28 M texels overflows Q15.16 and Q19.12: Q23.8 is chosen", "[analyze]") {
  const scene::Scene s = scene::load_scene(scene_file("huge_uv"));
  const std::vector<analyze::FormatChoice> choices = analyze::choose_formats(analyze::measure_ranges(s));
  const analyze::FormatChoice& uv = choice_named(choices, "uv x texture size");
  CHECK(rejected(uv, "Q15.16"));
  CHECK(rejected(uv, "Q19.12"));
  CHECK(chosen(uv) == "Q23.8");
}

TEST_CASE("coordinates of 21000 units overflow the pipeline's Q15.16, and prepare refuses them", "[analyze]") {
  const scene::Scene s = scene::load_scene(scene_file("far_positions"));
  const std::vector<analyze::FormatChoice> choices = analyze::choose_formats(analyze::measure_ranges(s));
  const analyze::FormatChoice& positions = choice_named(choices, "object positions");
  CHECK(rejected(positions, "Q15.16"));
  CHECK(chosen(positions) == "Q19.12");
  CHECK_FALSE(positions.candidates[*positions.chosen].implemented);
  CHECK_THROWS_AS(prepare::prepare_scene(s), prepare::PrepareError);  // the analysis agrees with prepare
}

TEST_CASE("surfaces 5e-6 apart in depth need 24 bits, and 16 bits do confuse them", "[analyze]") {
  const scene::Scene s = scene::load_scene(scene_file("thin_depth"));
  const analyze::SceneRanges ranges = analyze::measure_ranges(s);
  const std::vector<analyze::FormatChoice> choices = analyze::choose_formats(ranges);
  const analyze::FormatChoice& depth = choice_named(choices, "eye depth buffer");
  CHECK(rejected(depth, "16 bits"));
  CHECK(chosen(depth) == "24 bits");
  CHECK(analyze::required_depth_bits(choices) == 24);

  // The fixed pipeline shows the object the float model shows at 24 bits, not at 16.
  const auto prepared = prepare::prepare_scene(s);
  const sweep::CoordinateMap reference = sweep::float_coordinates(s);
  auto mismatches = [&](int bits) {
    Knobs knobs;
    knobs.depth_bits = static_cast<std::uint8_t>(bits);
    const sweep::CoordinateMap fixed = sweep::fixed_coordinates(*prepared, knobs);
    std::size_t n = 0;
    for (std::size_t p = 0; p < reference.pixels(); ++p) n += fixed.object[p] != reference.object[p];
    return n;
  };
  CHECK(mismatches(16) > ranges.depth.covered / 20);
  CHECK(mismatches(24) == 0);
}

TEST_CASE("an ordinary scene keeps the most precise formats and 16-bit depth", "[analyze]") {
  const scene::Scene s = scene::load_scene(std::filesystem::path(SPANLIGHT_SOURCE_DIR) / "scenes" / "textured_room.json");
  const std::vector<analyze::FormatChoice> choices = analyze::choose_formats(analyze::measure_ranges(s));
  CHECK(chosen(choice_named(choices, "object positions")) == "Q15.16");
  for (const analyze::FormatChoice& c : choices)
    if (c.quantity.rfind("uv", 0) == 0) CHECK(chosen(c) == "Q15.16");
  CHECK(analyze::required_depth_bits(choices) == 16);
}
