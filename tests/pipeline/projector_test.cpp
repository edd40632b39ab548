// Projector edge cases: geometry behind the projector (q < 0) and triangles
// that q = 0 cuts through. The sanitizer twin runs the same renders, so any
// division by zero, overflow or out-of-range shift on these paths aborts it.
#include <catch2/catch.hpp>

#include <climits>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fixedpoint/reciprocal.hpp"
#include "float_model/float_model.hpp"
#include "pipeline_support.hpp"
#include "spanlight/3_span/exact.hpp"

namespace pt = spanlight::ptest;
namespace sc = spanlight::scene;

TEST_CASE("geometry wholly behind the projector gets ambient light only, exactly", "[projector]") {
  // A quad in z = 0 facing the camera at z = 5; the projector at z = -3 looks
  // away from it, down -z. Its corners sit inside the mirror image of the
  // frustum (checked below): there s/q and t/q are in [0, 1] because both s
  // and q are negative, so only condition 1 (q > 0) must keep the light off
  // (condition 3 does too: r/q > 1 behind the eye).
  auto s = pt::empty_scene(96, 72, {0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40.0, 0.5, 20.0);
  s.ambient = glm::dvec3(0.2);
  s.textures.push_back(pt::texture("white", pt::solid_image(4, 4, {255, 255, 255}), sc::Filter::bilinear, sc::Wrap::clamp));
  s.objects.push_back(pt::quad("wall", {glm::dvec3(-1, -1, 0), glm::dvec3(1, -1, 0), glm::dvec3(1, 1, 0), glm::dvec3(-1, 1, 0)},
                               glm::dvec3(0.6)));
  s.projectors.push_back(pt::projector({0, 0, -3}, {0, 0, -10}, {0, 1, 0}, 60.0, 0.5, 20.0, 0, glm::dvec3(1.0)));

  const glm::dmat4 texture_matrix = sc::projector_texture_matrix(s.camera, s.projectors[0]);
  for (const glm::dvec3& corner : s.objects[0].mesh.positions) {
    const glm::dvec4 strq = texture_matrix * glm::dvec4(corner, 1.0);
    REQUIRE(strq.w < 0.0);
    REQUIRE(strq.x / strq.w >= 0.0);
    REQUIRE(strq.x / strq.w <= 1.0);
    REQUIRE(strq.y / strq.w >= 0.0);
    REQUIRE(strq.y / strq.w <= 1.0);
  }

  const auto prepared = spanlight::prepare::prepare_scene(s);
  const auto reference = spanlight::float_model::render_float(s);
  // ambient round(0.2 * 255) = 51, surface round(0.6 * 255) = 153;
  // modulate: round(51 * 153 / 255) = round(30.6) = 31. The float model:
  // round(255 * 0.2 * 0.6) = round(30.6) = 31 as well.
  constexpr std::uint8_t ambient_only = 31;
  for (const bool fused : {false, true}) {
    const spanlight::Knobs knobs = pt::knobs_with(fused ? spanlight::Passes::fused : spanlight::Passes::multipass);
    const auto frame = spanlight::prepare::render_fixed(*prepared, knobs);
    int covered = 0, wrong = 0, disagree_with_float = 0;
    for (std::size_t i = 0; i < frame.depth.size(); ++i) {
      if (frame.depth[i] == spanlight::depth_clear(24)) continue;
      ++covered;
      for (std::size_t c = 0; c < 3; ++c) {
        wrong += frame.rgb[i * 3 + c] != ambient_only;
        disagree_with_float += frame.rgb[i * 3 + c] != reference.rgb[i * 3 + c];
      }
    }
    INFO((fused ? "fused" : "multipass") << ": " << covered << " pixels covered");
    CHECK(covered > 1000);
    CHECK(wrong == 0);
    CHECK(disagree_with_float == 0);
  }
}

namespace {

// Everything about a pixel centre's floor point the lit test needs, in double.
struct FloorPoint {
  bool on_floor = false;  // the eye ray meets the floor quad
  bool lit = false;       // conditions 1-3 of the spec, exactly
  double q = 0.0;
  double s = 0.0, t = 0.0, r = 0.0;  // s/q, t/q, r/q
};

FloorPoint floor_point(const sc::Scene& s, const glm::dmat4& texture_matrix, double half_extent_x, double z_min,
                       double z_max, double px, double py) {
  FloorPoint out;
  glm::dvec3 hit;
  if (!pt::hit_plane_y(pt::pixel_ray(s, px, py), 0.0, hit)) return out;
  if (std::fabs(hit.x) > half_extent_x || hit.z < z_min || hit.z > z_max) return out;
  out.on_floor = true;
  const glm::dvec4 strq = texture_matrix * glm::dvec4(hit, 1.0);
  out.q = strq.w;
  out.s = strq.x / strq.w;
  out.t = strq.y / strq.w;
  out.r = strq.z / strq.w;
  const auto inside = [](double v) { return 0.0 <= v && v <= 1.0; };
  out.lit = strq.w > 0.0 && inside(strq.x / strq.w) && inside(strq.y / strq.w) && inside(strq.z / strq.w);
  return out;
}

}  // namespace

TEST_CASE("a floor that q = 0 cuts through is lit only where q > 0 and inside the frustum, as the float model says",
          "[projector]") {
  // pt::apex_floor_scene(): the projector's eye lies on the floor and looks
  // slightly down, so the plane q = 0 crosses the floor quad's two
  // triangles and the lit wedge's apex sits on the q = 0 line.
  //
  // Floor white, ambient 0.2 (51 levels), projector colour 0.5 (Q8.8 128:
  // 128 levels) and a white image with nearest filtering: a pixel is 51
  // unlit and 179 lit, nothing in between.
  auto s = pt::apex_floor_scene();
  const double half_x = pt::apex_floor_half_x, z_min = pt::apex_floor_z_min, z_max = pt::apex_floor_z_max;

  // Also with a shadow map: from an eye on the floor the floor is seen edge-on,
  // so its triangles have (nearly) zero area in the map, a degenerate case for
  // the shadow pass. Nothing may crash there; the picture is checked the same.
  for (const bool shadows : {false, true}) {
    if (shadows) s.projectors[0].shadows = sc::Shadows{64, 0.005, sc::ShadowFilter::pcf2x2};
    INFO((shadows ? "with" : "without") << " a shadow map");
    const glm::dmat4 texture_matrix = sc::projector_texture_matrix(s.camera, s.projectors[0]);

    // The exact picture at every pixel centre.
    std::vector<FloorPoint> exact(static_cast<std::size_t>(s.width * s.height));
    for (int y = 0; y < s.height; ++y)
      for (int x = 0; x < s.width; ++x)
        exact[static_cast<std::size_t>(y * s.width + x)] = floor_point(s, texture_matrix, half_x, z_min, z_max, x, y);

    const auto prepared = spanlight::prepare::prepare_scene(s);
    const auto reference = spanlight::float_model::render_float(s);
    const auto fixed = spanlight::prepare::render_fixed(*prepared, spanlight::Knobs{});

    // Where the fixed pipeline may disagree with the float model: its s/q and
    // t/q are within the span tolerance of the exact values (1/8 texel of the
    // 256-texel image = 2^-11) plus the reciprocal's error (8-bit table and a
    // Newton step: 2^-17 relative), and its vertices within 1/256 px; so a
    // pixel can only change sides where the exact boundary (frustum sides, the
    // near plane r/q = 0, the q = 0 line) passes within that distance of its
    // centre. Near the lit wedge s/q and t/q change by about 0.01 per pixel
    // (the wedge is ~2 units wide 4 units from the projector, ~20 px per unit
    // on screen), r/q faster still near the apex, all far more than 2^-11, so
    // such a pixel has a neighbour (8-neighbourhood) whose exact
    // classification differs. Only those are excused.
    int lit_fixed = 0, behind = 0, checked = 0, disagree = 0, excused = 0, fixed_vs_model = 0, in_between = 0,
        model_vs_exact = 0;
    std::string unexcused;
    for (int y = 1; y + 1 < s.height; ++y) {
      for (int x = 1; x + 1 < s.width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y * s.width + x);
        bool all_on_floor = true, near_boundary = false;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const FloorPoint& n = exact[static_cast<std::size_t>((y + dy) * s.width + x + dx)];
            all_on_floor &= n.on_floor;
            near_boundary |= n.lit != exact[i].lit;
          }
        }
        if (!all_on_floor) continue;  // the floor's own outline is the coverage tests' business
        ++checked;
        behind += exact[i].q < 0.0;
        const std::uint8_t value = fixed.rgb[i * 3];
        // Nothing in between: exactly unlit or exactly lit.
        in_between += value != 51 && value != 179;
        const bool fixed_lit = value > (51 + 179) / 2;
        const bool model_lit = reference.light_rgb[i * 3] > 0.2f + 0.25f;
        lit_fixed += fixed_lit;
        if (fixed_lit != model_lit) {
          ++disagree;
          if (near_boundary) {
            ++excused;
          } else {
            ++fixed_vs_model;
            std::ostringstream line;
            line << "pixel " << x << ", " << y << ": fixed " << (fixed_lit ? "lit" : "dark") << ", float model "
                 << (model_lit ? "lit" : "dark") << ", exact s/q t/q r/q " << exact[i].s << " " << exact[i].t << " "
                 << exact[i].r << ", q " << exact[i].q << "\n";
            if (fixed_vs_model <= 10) unexcused += line.str();
          }
        }
        // The float model itself follows the exact rule away from the boundary.
        if (!near_boundary) model_vs_exact += model_lit != exact[i].lit;
      }
    }
    INFO(checked << " floor pixels checked, " << behind << " behind the projector (q < 0), " << lit_fixed
                 << " lit, " << disagree << " disagree with the float model (" << excused << " within 1 px of a boundary)");
    INFO(unexcused);
    CHECK(behind > 2000);
    CHECK(lit_fixed > 1000);
    CHECK(in_between == 0);
    CHECK(model_vs_exact == 0);
    CHECK(fixed_vs_model == 0);
  }
}

TEST_CASE("a projector whose image is one texel lights as a larger image of the same colour does", "[projector]") {
  // The scene format allows a 1x1 projector image. draw_pass works out each projector's texel
  // scale from its image's larger side, 32 - clz32(size - 1): for size 1 that is clz32(0),
  // undefined (__builtin_clz(0); the sanitizer twin stops on it). A uniform image lights the same
  // at any size, so the 1x1 and the 2x2 white images must give the same bytes.
  auto scene_with_image = [](int size) {
    auto s = pt::empty_scene(64, 48, {0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 40.0, 0.5, 20.0);
    s.ambient = glm::dvec3(0.2);
    s.textures.push_back(pt::texture("white", pt::solid_image(size, size, {255, 255, 255}), sc::Filter::nearest,
                                     sc::Wrap::clamp));
    s.objects.push_back(pt::quad("wall", {glm::dvec3(-1, -1, 0), glm::dvec3(1, -1, 0), glm::dvec3(1, 1, 0),
                                          glm::dvec3(-1, 1, 0)}, glm::dvec3(0.6)));
    s.projectors.push_back(pt::projector({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 20.0, 0.5, 20.0, 0, glm::dvec3(0.5)));
    return s;
  };
  const auto one = spanlight::prepare::prepare_scene(scene_with_image(1));
  const auto two = spanlight::prepare::prepare_scene(scene_with_image(2));
  const auto a = spanlight::prepare::render_fixed(*one, spanlight::Knobs{});
  const auto b = spanlight::prepare::render_fixed(*two, spanlight::Knobs{});
  int lit = 0;
  for (std::size_t i = 0; i < b.rgb.size(); i += 3) lit += b.rgb[i] > 31;  // brighter than ambient alone
  CHECK(lit > 100);
  CHECK(a.rgb == b.rgb);
}

TEST_CASE("divide_q28 in word shifts is n * mantissa >> (shift - 28) saturated at +-2^30, for every d's length", "[projector]") {
  auto reference = [](std::int32_t n, const fixedpoint::Reciprocal& r) {
    const std::int64_t q = (std::int64_t{n} * r.mantissa) >> (r.shift - spanlight::proj_frac_bits);
    return q > spanlight::proj_limit ? spanlight::proj_limit : (q < -spanlight::proj_limit ? -spanlight::proj_limit : static_cast<std::int32_t>(q));
  };
  std::mt19937 random(20261207);
  long long wrong = 0, saturated = 0, compared = 0;
  auto check = [&](std::int32_t n, std::uint32_t d) {
    for (const fixedpoint::Reciprocal r : {fixedpoint::reciprocal<8, 1>(d), fixedpoint::reciprocal<6, 0>(d)}) {
      const std::int32_t expected = reference(n, r);
      wrong += spanlight::divide_q28(n, r) != expected;
      saturated += expected == spanlight::proj_limit || expected == -spanlight::proj_limit;
      ++compared;
    }
  };
  for (int length = 1; length <= 32; ++length) {  // d in [2^(length-1), 2^length): shift - 28 runs over [3, 34]
    const std::uint32_t low = 1u << (length - 1);
    for (const std::uint32_t d : {low, low + (low - 1u) / 2u, low + (low - 1u)}) {
      for (const std::int32_t n : {0, 1, -1, INT32_MAX, INT32_MIN + 1, 1 << 28, -(1 << 28)}) check(n, d);
    }
    for (int k = 0; k < 20000; ++k) {
      const std::uint32_t d = low + (length == 1 ? 0u : static_cast<std::uint32_t>(random()) % low);
      // n across its magnitudes, so each d sees quotients inside [-2^30, 2^30] and beyond.
      const auto n = static_cast<std::int32_t>(static_cast<std::uint32_t>(random()) >> (random() % 32u));
      check(k % 2 == 0 ? n : (n == INT32_MIN ? INT32_MIN + 1 : -n), d);
      // the boundary: n / d near +-4 (2^30 in Q3.28) for the d that allow it
      if (d < (1u << 29)) {
        const std::int32_t edge = static_cast<std::int32_t>(4 * d) + static_cast<std::int32_t>(random() % 5u) - 2;
        check(edge, d);
        check(-edge, d);
      }
    }
  }
  INFO(compared << " quotients, " << saturated << " saturated");
  CHECK(saturated > 1000);
  CHECK(wrong == 0);
}
