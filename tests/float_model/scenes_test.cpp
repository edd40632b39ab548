// The four example scenes render, and what they show is not trivial: surfaces
// fill the frame, projectors light some of them, shadow maps darken some lit
// pixels and brighten none. Pictures go to the build folder for a human look.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <set>
#include <string>

#include "compare/compare.hpp"
#include "float_model/float_model.hpp"
#include "scene/scene.hpp"

namespace fm = spanlight::float_model;
namespace scene = spanlight::scene;

namespace {

std::filesystem::path scene_file(const std::string& name) {
  return std::filesystem::path(SPANLIGHT_SOURCE_DIR) / "scenes" / (name + ".json");
}

// Pixels where some channel of the light is clearly above the ambient term.
long count_lit_by_projectors(const scene::Scene& s, const fm::FloatFrame& frame) {
  long lit = 0;
  for (std::size_t i = 0; i < frame.object.size(); ++i) {
    if (frame.object[i] < 0) continue;
    for (int c = 0; c < 3; ++c) {
      if (frame.light_rgb[i * 3 + static_cast<std::size_t>(c)] > s.ambient[c] + 0.02) {
        ++lit;
        break;
      }
    }
  }
  return lit;
}

}  // namespace

TEST_CASE("the example scenes render to non-trivial pictures", "[scenes]") {
  const std::string name = GENERATE(as<std::string>{}, "slide_projector", "spot_shadow", "three_projectors", "horizon");
  const scene::Scene s = scene::load_scene(scene_file(name));

  const auto start = std::chrono::steady_clock::now();
  const fm::FloatFrame frame = fm::render_float(s);
  const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
  std::cout << "render_float " << name << ": " << s.width << "x" << s.height << " in " << took.count() << " ms\n";

  REQUIRE(frame.width == s.width);
  REQUIRE(frame.height == s.height);
  REQUIRE(frame.rgb.size() == static_cast<std::size_t>(s.width * s.height * 3));
  const auto pixels = static_cast<long>(frame.object.size());
  const long drawn = pixels - std::count(frame.object.begin(), frame.object.end(), -1);
  CHECK(drawn > pixels * 3 / 10);
  std::set<std::array<std::uint8_t, 3>> colours;
  for (std::size_t i = 0; i < frame.rgb.size(); i += 3) colours.insert({frame.rgb[i], frame.rgb[i + 1], frame.rgb[i + 2]});
  CHECK(colours.size() > 100);
  CHECK(count_lit_by_projectors(s, frame) > 200);
  for (std::size_t i = 0; i < frame.depth.size(); ++i) {
    if (frame.object[i] >= 0) CHECK((frame.depth[i] >= 0.0 && frame.depth[i] < 1.0));
  }

  const auto out = std::filesystem::path(SPANLIGHT_TEST_OUTPUT_DIR) / (name + "_float.png");
  CHECK(spanlight::compare::write_png_atomically(out, frame.width, frame.height, frame.rgb));
}

TEST_CASE("shadow maps darken some lit pixels of the example scenes and brighten none", "[scenes][shadow]") {
  const std::string name = GENERATE(as<std::string>{}, "spot_shadow", "three_projectors");
  const scene::Scene s = scene::load_scene(scene_file(name));
  scene::Scene unshadowed = s;
  for (scene::Projector& p : unshadowed.projectors) p.shadows.reset();

  const fm::FloatFrame with = fm::render_float(s);
  const fm::FloatFrame without = fm::render_float(unshadowed);
  REQUIRE(with.object == without.object);  // shadows change light, never visibility
  long darker = 0;
  for (std::size_t i = 0; i < with.light_rgb.size(); ++i) {
    REQUIRE(with.light_rgb[i] <= without.light_rgb[i]);
    if (with.light_rgb[i] < without.light_rgb[i] - 0.05f) ++darker;
  }
  CHECK(darker > 500);
}
