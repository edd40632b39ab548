// Shadow maps on a scene whose shadow can be worked out by hand: a floor, a
// small square occluder above it, and a projector looking straight down.
//
//   floor     y = 0, |x|, |z| <= 2, white
//   occluder  y = 1, |x|, |z| <= 0.5, white, facing up
//   projector eye (0, 4, 0), looking at the origin, up -z, fovy 60, near 1,
//             far 10, white 512x512 image, colour 0.5, shadow map 512^2, bias 0.002
//
// The ray from the projector's eye to a floor point (x, 0, z) crosses y = 1 at
// (3/4 x, 1, 3/4 z), so the point is in shadow exactly when max(|x|, |z|) < 2/3.
// The frustum is 2 * 4 * tan(30 deg) = 4.62 units wide at the floor, wider than
// the floor, so every other floor point is lit. With ambient 0.2 (51 levels)
// and the projector adding round(128 * 255 / 256) = 128 levels, a floor pixel
// is 51 in shadow and 179 lit.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "pipeline_support.hpp"
#include "spanlight/4_pixel/shadow.hpp"

namespace pt = spanlight::ptest;
namespace sc = spanlight::scene;

namespace {

constexpr int map_size = 512;
constexpr double shadow_edge = 2.0 / 3.0;  // max(|x|, |z|) of the shadow's outline on the floor
constexpr std::uint8_t dark = 51, lit = 179;

sc::Scene shadow_scene(sc::ShadowFilter filter) {
  auto s = pt::empty_scene(240, 180, {0, 5, 6}, {0, 0, 0}, {0, 1, 0}, 45.0, 0.5, 30.0);
  s.ambient = glm::dvec3(0.2);
  s.textures.push_back(pt::texture("white", pt::solid_image(map_size, map_size, {255, 255, 255}), sc::Filter::nearest, sc::Wrap::clamp));
  s.objects.push_back(pt::quad("floor", {glm::dvec3(-2, 0, 2), glm::dvec3(2, 0, 2), glm::dvec3(2, 0, -2), glm::dvec3(-2, 0, -2)}));
  s.objects.push_back(pt::quad("occluder", {glm::dvec3(-0.5, 1, 0.5), glm::dvec3(0.5, 1, 0.5), glm::dvec3(0.5, 1, -0.5),
                                            glm::dvec3(-0.5, 1, -0.5)}));
  s.projectors.push_back(pt::projector({0, 4, 0}, {0, 0, 0}, {0, 0, -1}, 60.0, 1.0, 10.0, 0, glm::dvec3(0.5)));
  s.projectors[0].shadows = sc::Shadows{map_size, 0.002, filter};
  return s;
}

// One map texel on the floor: the frustum's width there over the map size.
const double texel_on_floor = 2.0 * 4.0 * std::tan(30.0 * 3.14159265358979323846 / 180.0) / map_size;  // 0.00902

// A nearest lookup decides by the map texel containing (s/q, t/q). That
// texel's centre was marked occluded by the coverage rule (with vertices
// snapped to 1/256 texel), so it is on the correct side unless the outline
// passes within half a texel diagonal (0.71 texel) of the point; the eye
// pass's s/q and t/q add at most the span tolerance, 1/8 texel of the
// projector's image, which is as large as the map for that reason (the span
// stage's tolerance does not look at the map's size). pcf2x2 reads the four
// texels whose centres are within one texel in each axis, so its result is
// mixed only within 1 + 0.71 texels. Two texels on the floor cover both
// (0.71 + 0.125 and 1.71 + 0.125 texels).
const double margin = 2.0 * texel_on_floor;

struct FloorPixel {
  bool usable = false;  // all of the 3x3 neighbourhood's rays land on the floor, none on the occluder
  double edge_distance = 0.0;  // max(|x|, |z|) - 2/3: < 0 in shadow; |.| bounds the distance to the outline
};

// Floor pixels farther than `margin` from the shadow's outline, on either side,
// and how many of them do not show that side's value.
struct ClearSides {
  int in_shadow = 0, in_light = 0, wrong_dark = 0, wrong_lit = 0;

  void add(double edge_distance, std::uint8_t value) {
    if (edge_distance < -margin) {
      ++in_shadow;
      wrong_dark += value != dark;
    } else if (edge_distance > margin) {
      ++in_light;
      wrong_lit += value != lit;
    }
  }
};

FloorPixel classify(const sc::Scene& s, int x, int y) {
  FloorPixel out{true, 0.0};
  for (int dy = -1; dy <= 1 && out.usable; ++dy) {
    for (int dx = -1; dx <= 1 && out.usable; ++dx) {
      const pt::Ray ray = pt::pixel_ray(s, x + dx, y + dy);
      glm::dvec3 top, floor;
      if (pt::hit_plane_y(ray, 1.0, top) && std::fabs(top.x) <= 0.5 && std::fabs(top.z) <= 0.5) out.usable = false;
      if (!pt::hit_plane_y(ray, 0.0, floor) || std::fabs(floor.x) > 1.95 || std::fabs(floor.z) > 1.95) out.usable = false;
      if (dx == 0 && dy == 0 && out.usable) out.edge_distance = std::max(std::fabs(floor.x), std::fabs(floor.z)) - shadow_edge;
    }
  }
  return out;
}

}  // namespace

TEST_CASE("nearest shadow compare: the floor under the occluder is dark, the rest lit", "[shadow]") {
  const auto s = shadow_scene(sc::ShadowFilter::nearest);
  const auto prepared = spanlight::prepare::prepare_scene(s);
  for (const bool fused : {false, true}) {
    const spanlight::Knobs knobs = pt::knobs_with(fused ? spanlight::Passes::fused : spanlight::Passes::multipass);
    const auto frame = spanlight::prepare::render_fixed(*prepared, knobs);
    ClearSides clear;
    int other = 0, worst_x = -1, worst_y = -1;
    double worst = 0.0;
    for (int y = 1; y + 1 < s.height; ++y) {
      for (int x = 1; x + 1 < s.width; ++x) {
        const FloorPixel p = classify(s, x, y);
        if (!p.usable) continue;
        const std::uint8_t value = frame.rgb[static_cast<std::size_t>(y * s.width + x) * 3];
        other += value != dark && value != lit;  // nearest: all or nothing
        const bool wrong = p.edge_distance < 0.0 ? value != dark : value != lit;
        if (wrong && std::fabs(p.edge_distance) > worst) {
          worst = std::fabs(p.edge_distance);
          worst_x = x;
          worst_y = y;
        }
        clear.add(p.edge_distance, value);
      }
    }
    INFO((fused ? "fused" : "multipass") << ": " << clear.in_shadow << " pixels clearly in shadow, " << clear.in_light
                                         << " clearly lit; margin " << margin << " units (2 map texels); farthest "
                                         << "misclassified pixel " << worst_x << ", " << worst_y << " at "
                                         << worst / texel_on_floor << " texels from the outline");
    CHECK(clear.in_shadow > 300);
    CHECK(clear.in_light > 3000);
    CHECK(other == 0);
    CHECK(clear.wrong_dark == 0);
    CHECK(clear.wrong_lit == 0);
  }
}

TEST_CASE("pcf2x2 gives intermediate light only near the shadow's outline", "[shadow]") {
  const auto s = shadow_scene(sc::ShadowFilter::pcf2x2);
  const auto prepared = spanlight::prepare::prepare_scene(s);
  const auto frame = spanlight::prepare::render_fixed(*prepared, spanlight::Knobs{});
  ClearSides clear;
  int mixed = 0, mixed_far = 0;
  for (int y = 1; y + 1 < s.height; ++y) {
    for (int x = 1; x + 1 < s.width; ++x) {
      const FloorPixel p = classify(s, x, y);
      if (!p.usable) continue;
      const std::uint8_t value = frame.rgb[static_cast<std::size_t>(y * s.width + x) * 3];
      const bool is_mixed = value > dark && value < lit;
      mixed += is_mixed;
      if (std::fabs(p.edge_distance) > margin) mixed_far += is_mixed;
      clear.add(p.edge_distance, value);
    }
  }
  INFO(clear.in_shadow << " pixels clearly in shadow, " << clear.in_light << " clearly lit, " << mixed << " in between");
  CHECK(mixed > 0);  // pcf does blend at the outline
  CHECK(mixed_far == 0);
  CHECK(clear.wrong_dark == 0);
  CHECK(clear.wrong_lit == 0);
}

TEST_CASE("the shadow compare in 32 bits (a stored depth against shadow_need) is r - bias <= depth in Q1.30", "[shadow]") {
  // r over the frustum's [0, 1] (Q3.28) and bias over what render_frame takes, [0, max_shadow_bias] (Q1.30),
  // against stored depths of 16 and 24 bits, at random and at the boundaries
  // 4 r - bias = d 2^k - 1, d 2^k, d 2^k + 1 where a wrong ceiling would show.
  std::mt19937_64 random(0x5ad0);
  long long wrong = 0, compared = 0;
  constexpr std::int32_t r_max = std::int32_t{1} << 28, bias_max = spanlight::max_shadow_bias;
  CHECK(bias_max == std::llround(1.99 * 1073741824.0));  // the 1.99 prepare clamps to
  for (const int depth_bits : {16, 24}) {
    const int k = 30 - depth_bits;
    const std::uint32_t top = (1u << depth_bits) - 1u;
    auto check = [&](std::int32_t r, std::int32_t bias, std::uint32_t stored) {
      const bool exact = 4 * std::int64_t{r} - bias <= (std::int64_t{stored} << k);
      wrong += exact != (stored >= spanlight::shadow_need(r, bias, depth_bits));
      ++compared;
    };
    for (int n = 0; n < 200000; ++n) {
      const auto stored = static_cast<std::uint32_t>(random() & top);
      const auto r = static_cast<std::int32_t>(random() % (r_max + 1ull));
      check(r, static_cast<std::int32_t>(random() % (bias_max + 1ull)), stored);
      // bias for 4 r - bias = stored 2^k + e, e in {-1, 0, 1}, where it is in range
      const std::int64_t near = 4 * std::int64_t{r} - (std::int64_t{stored} << k) - static_cast<std::int64_t>(random() % 3) + 1;
      if (near >= 0 && near <= bias_max) check(r, static_cast<std::int32_t>(near), stored);
    }
    for (const std::uint32_t stored : {0u, 1u, top - 1u, top})
      for (const std::int32_t r : {0, 1, r_max - 1, r_max})
        for (const std::int32_t bias : {0, 1, bias_max - 1, bias_max}) check(r, bias, stored);
  }
  INFO(compared << " compares");
  CHECK(wrong == 0);
}
