// Accuracy of the fixed pipeline against the float model on the shared
// scenes: the project's acceptance figures at the default settings, and the
// precision knobs moving the figures the way the sweep promises.
#include <catch2/catch.hpp>

#include <cstdio>
#include <string>
#include <vector>

#include "compare/compare.hpp"
#include "float_model/float_model.hpp"
#include "pipeline_support.hpp"

namespace pt = spanlight::ptest;
namespace cmp = spanlight::compare;

namespace {

struct Setting {
  int span_log2;
  int table_bits;
  int newton_steps;
};

cmp::CompareResult fixed_vs_float(const spanlight::prepare::PreparedStorage& prepared,
                                  const spanlight::float_model::FloatFrame& reference, Setting setting) {
  spanlight::Knobs knobs;  // rgb888, 24-bit depth, the default tolerance
  knobs.table_bits = static_cast<std::uint8_t>(setting.table_bits);
  knobs.newton = static_cast<std::uint8_t>(setting.newton_steps);
  knobs.span_log2 = static_cast<std::uint8_t>(setting.span_log2);
  const auto fixed = spanlight::prepare::render_fixed(prepared, knobs);
  return cmp::compare_images(cmp::Rgb8View{fixed.width, fixed.height, fixed.rgb},
                             cmp::Rgb8View{reference.width, reference.height, reference.rgb});
}

std::string describe(const char* scene, const char* setting, const cmp::CompareResult& r) {
  char line[256];
  std::snprintf(line, sizeof line, "%-17s %-26s PSNR %6.2f dB  max %3.0f LSB  mean %.3f LSB  >2 LSB %.3f %%  >8 LSB %.3f %%",
                scene, setting, r.psnr_db, r.max_abs_lsb, r.mean_abs_lsb, r.pct_over_2_lsb, r.pct_over_8_lsb);
  return line;
}

}  // namespace

// The acceptance figures are the project's own targets (PSNR >= 40 dB and at
// most 0.5 % of pixels off by more than 8 LSB), not fitted to the results.
TEST_CASE("default settings meet the acceptance figures on every shared scene, and span 1 with a 12-bit table does "
          "at least as well",
          "[accuracy]") {
  for (const char* name : pt::shared_scene_names()) {
    const auto loaded = spanlight::scene::load_scene(pt::scene_file(name));
    const auto prepared = spanlight::prepare::prepare_scene(loaded);
    const auto reference = spanlight::float_model::render_float(loaded);

    const spanlight::Knobs knobs{};
    const Setting defaults{knobs.span_log2, knobs.table_bits, knobs.newton};
    REQUIRE(defaults.span_log2 == 6);  // span 64, tolerance 2^-5, table 8, newton 1 is what "default" means below
    REQUIRE(knobs.tolerance_log2 == 5);
    REQUIRE(defaults.table_bits == 8);
    REQUIRE(defaults.newton_steps == 1);
    const cmp::CompareResult at_default = fixed_vs_float(*prepared, reference, defaults);
    const cmp::CompareResult at_best = fixed_vs_float(*prepared, reference, Setting{0, 12, 1});
    const std::string line_default = describe(name, "span 64, table 8, newton 1", at_default);
    const std::string line_best = describe(name, "span 1, table 12, newton 1", at_best);
    std::printf("%s\n%s\n", line_default.c_str(), line_best.c_str());
    INFO(line_default);
    INFO(line_best);
    CHECK(at_default.psnr_db >= 40.0);
    CHECK(at_default.pct_over_8_lsb <= 0.5);
    // "At least as well": no channel further off and no more pixels beyond 2 LSB. PSNR and the mean
    // are not ordered this way: where both renders are within 2 LSB everywhere they differ only in
    // which way single levels round (three_projectors: 51.108 against 51.111 dB, interpolation ahead).
    CHECK(at_best.max_abs_lsb <= at_default.max_abs_lsb);
    CHECK(at_best.pct_over_2_lsb <= at_default.pct_over_2_lsb);
  }
}

// The reciprocal's table and Newton steps are a real trade: at span 1 every
// pixel pays a divide, so a 6-bit table with no Newton step (relative error
// up to 2^-7 + 2^-16, fixedpoint/reciprocal.hpp) must show against 12 bits
// and one step (error below 2^-26 + 2^-29).
TEST_CASE("a 6-bit reciprocal table without Newton steps is less accurate than 12 bits with one step, at span 1",
          "[accuracy]") {
  const char* name = "slide_projector";
  const auto loaded = spanlight::scene::load_scene(pt::scene_file(name));
  const auto prepared = spanlight::prepare::prepare_scene(loaded);
  const auto reference = spanlight::float_model::render_float(loaded);
  const cmp::CompareResult coarse = fixed_vs_float(*prepared, reference, Setting{0, 6, 0});
  const cmp::CompareResult fine = fixed_vs_float(*prepared, reference, Setting{0, 12, 1});
  const std::string line_coarse = describe(name, "span 1, table 6, newton 0", coarse);
  const std::string line_fine = describe(name, "span 1, table 12, newton 1", fine);
  std::printf("%s\n%s\n", line_coarse.c_str(), line_fine.c_str());
  INFO(line_coarse);
  INFO(line_fine);
  CHECK(coarse.psnr_db < fine.psnr_db);
}
