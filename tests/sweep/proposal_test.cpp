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
                    spanlight::FilterChoice filter = spanlight::FilterChoice::scene) {
  sweep::SweepRow r;
  REQUIRE(set_knob(r.point.knobs, "span", std::to_string(span)) == KnobError::ok);
  REQUIRE(set_knob(r.point.knobs, "depth-bits", std::to_string(depth_bits)) == KnobError::ok);
  r.point.filter = filter;
  r.psnr_db = psnr;
  r.rms_lsb = 255.0 * std::pow(10.0, -psnr / 20.0);
  r.max_lsb = max_lsb;
  r.psnr_vs_scene_db = psnr;
  r.rms_vs_scene_lsb = r.rms_lsb;
  r.max_vs_scene_lsb = max_lsb;
  r.m7.instructions = m7;
  r.m7.source = "measured";
  r.is_default = r.point == sweep::GridPoint{};
  return r;
}

sweep::SweepResult sample() {
  sweep::SweepResult r;
  r.scene_name = "sample";
  r.format = "rgb888";
  r.covered_pixels = 1000;
  r.rows = {row(1, 24, 50, 4, 90), row(4, 24, 46, 9, 60), row(64, 24, 42, 30, 50), row(32, 24, 38, 60, 45),
            row(32, 16, 38, 60, 44), row(16, 16, 42, 30, 49), row(32, 24, 48, 5, 20, spanlight::FilterChoice::nearest)};
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
  sweep::GridPoint config{Knobs{.span_log2 = 3, .tolerance_log2 = 2, .table_bits = 10, .newton = 0, .depth_bits = 16,
                                .format = PixelFormat::rgb565_be, .passes = Passes::multipass, .mip = MipRule::segment},
                          spanlight::FilterChoice::nearest};
  {
    std::ofstream(dir / "good.json") << analyze::to_json(config, R"({"psnr_db": 40})");
  }
  CHECK(analyze::read_knob_config(dir / "good.json") == config);

  // Every knob by its knob_table name, values as typed (numbers as JSON numbers or strings).
  const std::string good = R"({"spanlight_knobs": 3, "span": "8", "tolerance": 2, "table-bits": 10, "newton": 0,
      "depth-bits": 16, "format": "rgb565-be", "passes": "multipass", "mip": "segment", "texture_filter": "nearest"})";
  auto refused = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
  };
  refused("typed.json", good);
  CHECK(analyze::read_knob_config(dir / "typed.json") == config);
  auto replace = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    text.replace(text.find(from), from.size(), to);
    return text;
  };
  refused("bad_span.json", replace(R"("span": "8")", R"("span": 3)"));
  CHECK_THROWS_WITH(analyze::read_knob_config(dir / "bad_span.json"),
                    Catch::Matchers::Contains("bad_span.json: span: expected one of 1, 2, 4, 8, 16, 32, 64, not \"3\""));
  refused("bad_format.json", replace(R"("rgb565-be")", R"("rgb555")"));
  CHECK_THROWS_WITH(analyze::read_knob_config(dir / "bad_format.json"), Catch::Matchers::Contains("format: expected one of"));
  refused("missing_passes.json", replace(R"("passes": "multipass",)", ""));
  CHECK_THROWS_WITH(analyze::read_knob_config(dir / "missing_passes.json"), Catch::Matchers::Contains("passes: expected one of fused, multipass (missing)"));
  refused("negative.json", replace(R"("newton": 0)", R"("newton": -1)"));
  CHECK_THROWS_WITH(analyze::read_knob_config(dir / "negative.json"), Catch::Matchers::Contains("newton: expected one of"));
  refused("bad_filter.json", replace(R"("nearest")", R"("trilinear")"));
  CHECK_THROWS_WITH(analyze::read_knob_config(dir / "bad_filter.json"), Catch::Matchers::Contains("texture_filter: expected one of"));
  refused("version2.json", replace(R"("spanlight_knobs": 3)", R"("spanlight_knobs": 2)"));
  CHECK_THROWS_WITH(analyze::read_knob_config(dir / "version2.json"), Catch::Matchers::Contains("spanlight_knobs: expected 3"));
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
    CHECK(back.rows[i].point == r.rows[i].point);
    CHECK(back.rows[i].m7.instructions == r.rows[i].m7.instructions);
    CHECK(back.rows[i].front_m7 == r.rows[i].front_m7);
    CHECK(back.rows[i].is_default == r.rows[i].is_default);
  }
  CHECK(std::isinf(back.rows[0].psnr_db));
  CHECK_FALSE(back.rows[1].m0plus.instructions);
  CHECK(back.rows[1].m0plus.source == "n/a: not built");
  CHECK(back.rows[2].flash_m7 == std::optional<std::size_t>{12345});
}

TEST_CASE("a sweep CSV with a knob value set_knob refuses is refused with the line and the column", "[sweep]") {
  const std::string text = sweep::to_csv(sample());
  const std::filesystem::path file = std::filesystem::temp_directory_path() / "spanlight_sweep_csv_bad.csv";
  auto refusal = [&](const std::string& from, const std::string& to) {
    std::string bad = text;
    const std::size_t line2 = bad.find('\n') + 1;
    const std::size_t at = bad.find(from, line2);
    REQUIRE(at != std::string::npos);
    bad.replace(at, from.size(), to);
    {
      std::ofstream(file) << bad;
    }
    std::string message;
    try {
      (void)sweep::read_csv(file);
    } catch (const std::runtime_error& e) {
      message = e.what();
    }
    std::filesystem::remove(file);
    return message;
  };
  CHECK_THAT(refusal(",fused,", ",fusd,"), Catch::Matchers::Contains("line 2: passes: expected one of fused, multipass"));
  CHECK_THAT(refusal(",rgb888,", ",rgb999,"), Catch::Matchers::Contains("line 2: format: expected one of"));
  CHECK_THAT(refusal(",scene,", ",linear,"), Catch::Matchers::Contains("line 2: texture filter"));
}
