// The proposal: the cheapest row meeting the target within the constraints,
// and the bake config file that carries it.
#include <cmath>
#include <filesystem>
#include <fstream>

#include <catch2/catch.hpp>

#include "analyze/knob_config.hpp"
#include "analyze/proposal.hpp"
#include "sweep/csv_io.hpp"
#include "sweep/sweep_run.hpp"

using namespace spanlight;

namespace {

sweep::SweepRow row(int span, int depth_bits, double psnr, double max_lsb, std::uint64_t m7,
                    sweep::FilterChoice filter = sweep::FilterChoice::scene) {
  sweep::SweepRow r;
  r.config.span = span;
  r.config.depth_bits = depth_bits;
  r.config.filter = filter;
  r.psnr_db = psnr;
  r.rms_lsb = 255.0 * std::pow(10.0, -psnr / 20.0);
  r.max_lsb = max_lsb;
  r.psnr_vs_scene_db = psnr;
  r.rms_vs_scene_lsb = r.rms_lsb;
  r.max_vs_scene_lsb = max_lsb;
  r.m7.instructions = m7;
  r.m7.source = "measured";
  r.is_default = r.config == sweep::default_config();
  return r;
}

sweep::SweepResult sample() {
  sweep::SweepResult r;
  r.scene_name = "sample";
  r.format = "rgb888";
  r.covered_pixels = 1000;
  r.rows = {row(1, 24, 50, 4, 90), row(4, 24, 46, 9, 60), row(16, 24, 42, 30, 50), row(32, 24, 38, 60, 45),
            row(32, 16, 38, 60, 44), row(16, 16, 42, 30, 49), row(32, 24, 48, 5, 20, sweep::FilterChoice::nearest)};
  return r;
}

}  // namespace

TEST_CASE("the cheapest row meeting a PSNR target", "[analyze]") {
  const sweep::SweepResult r = sample();
  analyze::AccuracyTarget target;
  target.min_psnr_db = 45;
  const analyze::Proposal p = analyze::cheapest_meeting(r, target, {});
  REQUIRE(p.row);
  CHECK(*p.row == 1);  // span 4: the nearest-filter row is cheaper but changes the scene
  CHECK(p.axis == sweep::CostAxis::m7);

  analyze::Constraints filters_allowed;
  filters_allowed.allow_filter_change = true;
  CHECK(*analyze::cheapest_meeting(r, target, filters_allowed).row == 6);
}

TEST_CASE("depth bits below what the scene needs are never proposed", "[analyze]") {
  const sweep::SweepResult r = sample();
  analyze::AccuracyTarget target;
  target.min_psnr_db = 37;
  CHECK(*analyze::cheapest_meeting(r, target, {16, false}).row == 4);  // 16 bits allowed: the cheapest
  CHECK(*analyze::cheapest_meeting(r, target, {24, false}).row == 3);  // the scene needs 24 bits
}

TEST_CASE("a max-error target, the default target, and an impossible one", "[analyze]") {
  const sweep::SweepResult r = sample();
  analyze::AccuracyTarget max_error;
  max_error.max_error_lsb = 10;
  CHECK(*analyze::cheapest_meeting(r, max_error, {}).row == 1);
  // No target: at least as accurate as the default (row 2, PSNR 42): row 5 matches it for less.
  CHECK(*analyze::cheapest_meeting(r, {}, {}).row == 5);
  analyze::AccuracyTarget impossible;
  impossible.min_psnr_db = 80;
  const analyze::Proposal none = analyze::cheapest_meeting(r, impossible, {});
  CHECK_FALSE(none.row);
  CHECK(none.why_none.find("PSNR >= 80") != std::string::npos);
}

TEST_CASE("a knob config survives writing and reading - bad ones are refused with the field", "[analyze]") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "spanlight_knob_config_test";
  std::filesystem::create_directories(dir);
  analyze::KnobConfig config;
  config.knobs = {8, 2, 10, 0, 16, true, sweep::FilterChoice::nearest};
  config.format = PixelFormat::rgb565;
  {
    std::ofstream(dir / "good.json") << analyze::to_json(config, R"({"psnr_db": 40})");
  }
  const analyze::KnobConfig back = analyze::read_knob_config(dir / "good.json");
  CHECK(back.knobs == config.knobs);
  CHECK(back.format == PixelFormat::rgb565);

  {
    std::ofstream(dir / "bad_span.json") << R"({"spanlight_knobs": 1, "span": 3, "tolerance": 3, "table_bits": 8,
      "newton": 1, "depth_bits": 24, "format": "rgb888", "fused": false, "texture_filter": "scene"})";
  }
  CHECK_THROWS_WITH(analyze::read_knob_config(dir / "bad_span.json"), Catch::Matchers::Contains("span: expected one of"));
  {
    std::ofstream(dir / "not_json.json") << "{span";
  }
  CHECK_THROWS_WITH(analyze::read_knob_config(dir / "not_json.json"), Catch::Matchers::Contains("not JSON"));
  CHECK_THROWS(analyze::read_knob_config(dir / "missing.json"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("the sweep CSV reads back what was written", "[sweep]") {
  sweep::SweepResult r = sample();
  r.rows[0].psnr_db = INFINITY;
  r.rows[1].m0plus.source = "n/a: not built";
  r.rows[2].flash_m7 = 12345;
  sweep::mark_fronts(r);
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "spanlight_sweep_csv_test.csv";
  {
    std::ofstream(file) << sweep::to_csv(r);
  }
  const sweep::SweepResult back = sweep::read_csv(file);
  std::filesystem::remove(file);
  REQUIRE(back.rows.size() == r.rows.size());
  CHECK(back.scene_name == "sample");
  CHECK(back.covered_pixels == 1000);
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    CHECK(back.rows[i].config == r.rows[i].config);
    CHECK(back.rows[i].m7.instructions == r.rows[i].m7.instructions);
    CHECK(back.rows[i].front_m7 == r.rows[i].front_m7);
    CHECK(back.rows[i].is_default == r.rows[i].is_default);
  }
  CHECK(std::isinf(back.rows[0].psnr_db));
  CHECK_FALSE(back.rows[1].m0plus.instructions);
  CHECK(back.rows[1].m0plus.source == "n/a: not built");
  CHECK(back.rows[2].flash_m7 == std::optional<std::size_t>{12345});
}
