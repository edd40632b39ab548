// Depth at its extremes: window depths near 0 and near 1, 16-bit depth over a
// deep range, in the multipass and the fused plan.
//
// Window depth is z_w = f (z - n) / ((f - n) z) for a surface at distance z
// (spec: (z/w + 1) / 2), so 1 - z_w = n (f - z) / ((f - n) z) and the gap
// between two surfaces dz apart is about n dz / z^2. The depth buffer keeps
// the top depth_bits of the Q1.30 value (4_pixel/depth.hpp, DepthFormat::store: truncation),
// and is cleared to all ones.
#include <catch2/catch.hpp>

#include <cmath>

#include "extremes_support.hpp"

using namespace spanlight::xt;

namespace {

constexpr int tolerance = 3;  // levels, as in near_plane_test.cpp

spanlight::Knobs with_depth(int bits, bool fused) {
  spanlight::Knobs o = with_passes(default_options(), fused);
  o.depth_bits = static_cast<std::uint8_t>(bits);
  return o;
}

// Camera at the origin looking down -z; a 1x1-texel white projector from
// beside the eye lights everything in front.
sc::Scene facing(double near, double far) {
  sc::Scene s = make_scene(64, 48, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0, near, far);
  s.ambient = glm::dvec3(0.2);
  s.textures.push_back(texture("white", solid_image(1, 1, {255, 255, 255}), sc::Filter::nearest, sc::Wrap::clamp));
  s.projectors.push_back(projector({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 100.0, near / 2, far * 1.5, 0, glm::dvec3(0.5)));
  return s;
}

// A square facing the eye at distance z, `half` times z wide on each side.
sc::Object square_at(const std::string& name, double z, double half, glm::dvec3 color) {
  const double h = half * z;
  return quad(name, {glm::dvec3(-h, -h, -z), glm::dvec3(h, -h, -z), glm::dvec3(h, h, -z), glm::dvec3(-h, h, -z)}, color);
}

// 1 - z_w for a surface at distance z.
double depth_gap_to_one(double near, double far, double z) { return near * (far - z) / ((far - near) * z); }

}  // namespace

TEST_CASE("window depth near 0: a surface just beyond the near plane is drawn and nearest", "[extremes][depth]") {
  // z = near * (1 + 2^-20): z_w ~ 2^-20, a few 24-bit steps above 0.
  const double near = 0.25;
  sc::Scene s = facing(near, 100.0);
  s.objects.push_back(square_at("far", 10.0, 0.3, glm::dvec3(0.2, 0.4, 0.9)));
  s.objects.push_back(square_at("at_near", near * (1.0 + std::ldexp(1.0, -20)), 0.2, glm::dvec3(0.9, 0.6, 0.3)));
  snap_positions_to_q16(s);
  for (const int bits : {16, 24}) {
    const Both b = render_both(s, with_depth(bits, false));
    const Agreement a = agree(b, 1, tolerance);
    INFO(bits << "-bit depth: " << describe(a, s.width));
    CHECK(a.covered_ref > 500);
    CHECK(a.unexplained == 0);
    int smallest = 1 << 30;
    for (const std::uint32_t d : b.fixed.depth) smallest = std::min(smallest, static_cast<int>(d));
    CHECK(smallest <= 16);  // stored depth within 16 steps of 0
  }
}

TEST_CASE("16-bit depth over a deep range: z-fighting picks one surface per pixel, never a mix, and never crashes",
          "[extremes][depth]") {
  // near 0.01, far 1000 (far/near 1e5); two squares 0.5 apart at distance 60:
  // their window depths differ by about n dz / z^2 = 1.4e-6, which is 23
  // steps of 24-bit depth but 0.09 of a 16-bit step. With 24 bits the nearer
  // one shows everywhere (as in the float model); with 16 bits both quantise
  // to the same stored value over most of the square and the first drawn
  // wins those ties (depth test `less`). Either way each pixel shows exactly
  // one surface's colour, lit once: the light and modulate passes claim a
  // pixel once (4_pixel/depth.hpp, the tie mask).
  sc::Scene s = facing(0.01, 1000.0);
  s.objects.push_back(square_at("behind", 60.5, 0.25, glm::dvec3(0.9, 0.3, 0.2)));  // drawn first
  s.objects.push_back(square_at("front", 60.0, 0.25, glm::dvec3(0.2, 0.5, 0.9)));  // the same outline on screen
  snap_positions_to_q16(s);
  const double gap = depth_gap_to_one(0.01, 1000.0, 60.0) - depth_gap_to_one(0.01, 1000.0, 60.5);
  INFO("window-depth gap " << gap << " = " << gap * 65536.0 << " 16-bit steps, " << gap * 16777216.0 << " 24-bit steps");

  // Reference colours of the two surfaces: from the float model's 24-bit-agreeing render.
  const Both b24 = render_both(s, with_depth(24, false));
  const Agreement a24 = agree(b24, 1, tolerance);
  INFO("24-bit: " << describe(a24, s.width));
  CHECK(a24.unexplained == 0);

  for (const bool fused : {false, true}) {
    const Both b16 = render_both(s, with_depth(16, fused));
    int overlap = 0, shows_behind = 0, shows_front = 0, other = 0;
    for (std::size_t i = 0; i < b16.ref.object.size(); ++i) {
      if (b16.ref.object[i] != 1) continue;  // the front square in the float model
      ++overlap;
      const int to_front = channel_diff(b16.fixed.rgb, b16.ref.rgb, i, i);
      // The behind square's colour under the same light as the front one.
      const std::uint8_t behind_r = fm::to_byte(b16.ref.light_rgb[i * 3] * 0.9),
                         behind_g = fm::to_byte(b16.ref.light_rgb[i * 3 + 1] * 0.3),
                         behind_b = fm::to_byte(b16.ref.light_rgb[i * 3 + 2] * 0.2);
      const int to_behind = std::max({std::abs(int{b16.fixed.rgb[i * 3]} - behind_r), std::abs(int{b16.fixed.rgb[i * 3 + 1]} - behind_g),
                                      std::abs(int{b16.fixed.rgb[i * 3 + 2]} - behind_b)});
      if (to_front <= tolerance) ++shows_front;
      else if (to_behind <= tolerance) ++shows_behind;
      else ++other;
    }
    INFO((fused ? "fused" : "multipass") << ": front square " << overlap << " pixels: shows front " << shows_front
                                          << ", shows behind " << shows_behind << ", other " << other);
    CHECK(overlap > 300);
    CHECK(other == 0);
    CHECK(shows_behind > 0);       // the trade is real: 16 bits cannot separate them
  }
  // The multipass and fused plans make the same choice at every pixel.
  const Both multi = render_both(s, with_depth(16, false));
  const Both fused = render_both(s, with_depth(16, true));
  CHECK(pixels_differing(multi.fixed.rgb, fused.fixed.rgb, 0) == 0);
  CHECK(multi.fixed.depth == fused.fixed.depth);
}

TEST_CASE("window depth near 1: a surface in the last depth step before the far plane is drawn like any other",
          "[extremes][depth]") {
  // Regression (found by this suite, fixed; docs/limits.md): DepthFormat::store (4_pixel/depth.hpp) truncates the Q1.30 depth to
  // depth_bits and clamps it to depth_clear(bits), the value the buffer is
  // cleared to. A fragment with 1 - z_w < 2^-depth_bits therefore stores the
  // clear value and the depth pass (`d < Z`) drops it; the z-equal passes
  // skip cleared pixels (passes.hpp), so the surface is simply missing, in the
  // multipass and the fused plan alike. The float model draws it (any depth
  // < 1 passes its `less` test against the cleared 1). With near n and far f
  // this is every surface beyond z = f / (1 + 2^-bits f / n): the last 1.5%
  // of the range at n = 0.1, f = 100 with 16 bits; everything beyond 614 m
  // at n = 0.01, f = 1e4 with 16 bits; beyond 9.4 km there with 24 bits.
  // The fix: depth_store clamps to depth_clear(bits) - 1, so a drawn
  // fragment never stores the clear value.
  for (const int bits : {16, 24}) {
    const double near = 1.0, far = 1000.0;
    // Distance whose 1 - z_w is half a depth step: inside the last step.
    const double step = std::ldexp(1.0, -bits);
    double z = far / (1.0 + 0.5 * step * far / near);
    sc::Scene s = facing(near, far);
    s.objects.push_back(square_at("last_step", z, 0.3, glm::dvec3(0.8, 0.8, 0.3)));
    snap_positions_to_q16(s);
    z = -s.objects[0].mesh.positions[0].z;
    INFO(bits << "-bit depth, surface at " << z << ": 1 - z_w = " << depth_gap_to_one(near, far, z) << " = "
              << depth_gap_to_one(near, far, z) / step << " steps");
    for (const bool fused : {false, true}) {
      const Both b = render_both(s, with_depth(bits, fused));
      const Agreement a = agree(b, 1, tolerance);
      INFO((fused ? "fused: " : "multipass: ") << describe(a, s.width));
      CHECK(a.covered_ref > 500);
      CHECK(a.covered_fixed == a.covered_ref);
      CHECK(a.unexplained == 0);
    }
  }
}
