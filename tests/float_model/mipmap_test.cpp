// Trilinear filtering in the float model: the level of detail from the exact
// screen derivatives of the perspective mapping, and the mix of two levels.
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <catch2/catch.hpp>

#include "float_model/raster.hpp"
#include "float_model/sample.hpp"
#include "scene/mip_chain.hpp"
#include "test_scenes.hpp"

namespace fm = spanlight::float_model;
namespace scene = spanlight::scene;

namespace {

// A clip-space vertex whose window position is (x, y) pixels (y down) in a
// width x height viewport, at clip w = `w` (depth mid-range).
fm::ClipVertex at_window(double x, double y, double w, glm::dvec2 uv, int width, int height) {
  fm::ClipVertex v;
  const double ndc_x = 2.0 * x / width - 1.0;
  const double ndc_y = 1.0 - 2.0 * y / height;
  v.position = glm::dvec4(ndc_x * w, ndc_y * w, 0.0, w);
  v.uv = uv;
  return v;
}

// Screen barycentrics of point p in triangle (a, b, c), written out independently of setup.cpp.
std::array<double, 3> barycentrics(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 p) {
  const auto cross = [](glm::dvec2 u, glm::dvec2 v) { return u.x * v.y - u.y * v.x; };
  const double area = cross(b - a, c - a);
  return {cross(b - p, c - p) / area, cross(c - p, a - p) / area, cross(a - p, b - p) / area};
}

}  // namespace

TEST_CASE("a screen-filling square with uv scaled by 2^k has lambda = k", "[float_model][mip]") {
  constexpr int size = 64;  // viewport and texture: one texel per pixel at k = 0
  for (int k = -3; k <= 6; ++k) {
    INFO("k = " << k);
    const double s = std::ldexp(1.0, k);
    for (const double w : {1.0, 2.5}) {  // the same mapping with any constant w
      const fm::ClipVertex v00 = at_window(0, size, w, {0, 0}, size, size);
      const fm::ClipVertex v10 = at_window(size, size, w, {s, 0}, size, size);
      const fm::ClipVertex v11 = at_window(size, 0, w, {s, s}, size, size);
      const fm::ClipVertex v01 = at_window(0, 0, w, {0, s}, size, size);
      int pixels = 0;
      for (const fm::ClipTriangle& triangle : {fm::ClipTriangle{v00, v10, v11}, fm::ClipTriangle{v00, v11, v01}}) {
        fm::rasterize_clipped(triangle, {size, size}, scene::Cull::none, [&](const fm::ClipTriangle& t, const fm::Fragment& f) {
          const fm::UvDerivatives d = fm::uv_derivatives(t, f);
          // U = u * 64 grows by 2^k per pixel to the right; V by 2^k per pixel upwards (y down: -2^k).
          CHECK(d.d_dx.x * size == Approx(s).margin(1e-12 * s));
          CHECK(d.d_dx.y == Approx(0.0).margin(1e-12 * s));
          CHECK(d.d_dy.y * size == Approx(-s).margin(1e-12 * s));
          CHECK(fm::level_of_detail(d.d_dx, d.d_dy, size, size) == Approx(k).margin(1e-12));
          ++pixels;
        });
      }
      CHECK(pixels == size * size);  // each pixel once
    }
  }
}

TEST_CASE("uv derivatives equal those of the perspective mapping at the pixel centre", "[float_model][mip]") {
  // Random triangles on the 1/256 grid (so snapping moves nothing) with random w and uv. The
  // reference is the closed form uv(p) = sum(b_i uv_i / w_i) / sum(b_i / w_i) with barycentrics
  // written out here, differentiated by central differences with step h = 2^-10 px. The
  // truncation error is (h^2 / 6) |uv'''|; uv = N / D with D = sum b_i / w_i affine, so
  // along any line uv is a Moebius function of the step and uv''' = 6 uv' (D' / D)^2. With
  // 1/w in [1/4, 1] and every altitude at least 16 px, D' = sum_{i=1,2} grad b_i (1/w_i - 1/w_0)
  // is at most 2 * (3/4) / 16 per px and D >= 1/4, so |D'| / D <= 0.375 and the error is below
  // h^2 * 0.15 |uv'| < 2e-7 |uv'|; rounding adds ~1e-12 / h. Bound: 1e-6 of the derivative.
  constexpr int width = 128, height = 96;
  std::mt19937 random(2024);
  std::uniform_int_distribution<int> coordinate(0, 128 * 256);
  std::uniform_real_distribution<double> w_of(1.0, 4.0), uv_of(-3.0, 3.0);
  int checked = 0;
  for (int n = 0; n < 200; ++n) {
    std::array<glm::dvec2, 3> window{};
    fm::ClipTriangle triangle;
    std::array<double, 3> w{};
    for (std::size_t i = 0; i < 3; ++i) {
      window[i] = {coordinate(random) / 256.0, std::min(coordinate(random), 96 * 256) / 256.0};
      w[i] = w_of(random);
      triangle[i] = at_window(window[i].x, window[i].y, w[i], {uv_of(random), uv_of(random)}, width, height);
    }
    const auto cross = [](glm::dvec2 u, glm::dvec2 v) { return u.x * v.y - u.y * v.x; };
    const double twice_area = std::abs(cross(window[1] - window[0], window[2] - window[0]));
    const double longest = std::max({glm::length(window[1] - window[0]), glm::length(window[2] - window[1]),
                                     glm::length(window[0] - window[2])});
    if (!(twice_area / longest >= 16.0)) continue;  // the smallest altitude, see the bound above
    const auto uv_at = [&](glm::dvec2 p) {
      const auto b = barycentrics(window[0], window[1], window[2], p);
      glm::dvec2 num(0.0);
      double den = 0.0;
      for (std::size_t i = 0; i < 3; ++i) {
        num += b[i] * triangle[i].uv / w[i];
        den += b[i] / w[i];
      }
      return num / den;
    };
    fm::rasterize_clipped(triangle, {width, height}, scene::Cull::none, [&](const fm::ClipTriangle& t, const fm::Fragment& f) {
      const glm::dvec2 centre(f.x + 0.5, f.y + 0.5);
      const double h = std::ldexp(1.0, -10);
      const glm::dvec2 dx = (uv_at(centre + glm::dvec2(h, 0)) - uv_at(centre - glm::dvec2(h, 0))) / (2 * h);
      const glm::dvec2 dy = (uv_at(centre + glm::dvec2(0, h)) - uv_at(centre - glm::dvec2(0, h))) / (2 * h);
      const fm::UvDerivatives d = fm::uv_derivatives(t, f);
      const double scale = std::max({glm::length(dx), glm::length(dy), 1e-3});
      CHECK(glm::length(d.d_dx - dx) <= 1e-6 * scale);
      CHECK(glm::length(d.d_dy - dy) <= 1e-6 * scale);
      ++checked;
    });
  }
  CHECK(checked > 1000);
}

TEST_CASE("trilinear: bilinear at level 0 for lambda <= 0, else two levels mixed by lambda's fraction", "[float_model][mip]") {
  // A hand-made chain of constant levels: 0, 100, 200 (grey), so each level's bilinear value is its constant.
  const std::vector<scene::Image> chain = {spanlight::test::solid_image(4, 4, {0, 0, 0}),
                                           spanlight::test::solid_image(2, 2, {100, 100, 100}),
                                           spanlight::test::solid_image(1, 1, {200, 200, 200})};
  const auto grey = [&](double lambda) {
    return fm::sample_trilinear(chain, scene::Wrap::repeat, {0.3, 0.7}, lambda).r * 255.0;
  };
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(grey(-inf) == 0.0);
  CHECK(grey(-1.0) == 0.0);
  CHECK(grey(0.0) == 0.0);
  CHECK(grey(std::numeric_limits<double>::quiet_NaN()) == 0.0);
  CHECK(grey(0.25) == Approx(25.0));   // 0.75 * 0 + 0.25 * 100
  CHECK(grey(1.0) == Approx(100.0));
  CHECK(grey(1.5) == Approx(150.0));
  CHECK(grey(2.0) == Approx(200.0));   // the last level
  CHECK(grey(7.3) == Approx(200.0));   // clamped to the last level
  CHECK(grey(inf) == Approx(200.0));
}

TEST_CASE("trilinear samples each level bilinearly with the texture's wrap", "[float_model][mip]") {
  // Level 0 a 2x2 image: black left column, white right column; level 1 its 1x1 mean 128.
  scene::Image image{2, 2, {0, 0, 0, 255, 255, 255, 0, 0, 0, 255, 255, 255}};
  const std::vector<scene::Image> chain = scene::mip_chain(image);
  REQUIRE(chain.size() == 2);
  // u = 0: halfway between texel 0's centre and (wrapped) texel 1's: repeat mixes, clamp keeps black.
  CHECK(fm::sample_trilinear(chain, scene::Wrap::repeat, {0.0, 0.5}, 0.0).r * 255 == Approx(127.5));
  CHECK(fm::sample_trilinear(chain, scene::Wrap::clamp, {0.0, 0.5}, 0.0).r * 255 == Approx(0.0));
  CHECK(fm::sample_trilinear(chain, scene::Wrap::clamp, {0.0, 0.5}, 0.5).r * 255 == Approx(0.5 * 0 + 0.5 * 128));
  CHECK(fm::sample_trilinear(chain, scene::Wrap::border, {0.0, 0.5}, 1.0).r * 255 == Approx(64.0));  // 128 blended toward black
}

TEST_CASE("level_of_detail: log2 of the longer derivative vector in level-0 texels", "[float_model][mip]") {
  CHECK(fm::level_of_detail({1.0 / 64, 0}, {0, 1.0 / 64}, 64, 64) == 0.0);
  CHECK(fm::level_of_detail({3.0 / 64, 0}, {0, 4.0 / 32}, 64, 32) == Approx(2.0));  // |(0, 4)| > |(3, 0)|
  CHECK(fm::level_of_detail({3.0 / 64, 4.0 / 32}, {0, 0}, 64, 32) == Approx(std::log2(5.0)));  // |(3, 4)| = 5
  CHECK(fm::level_of_detail({0, 0}, {0, 0}, 64, 64) == -std::numeric_limits<double>::infinity());
}
