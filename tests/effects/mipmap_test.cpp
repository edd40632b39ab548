// trilinear: a one-texel checker floor seen at a distance converges to its mean grey.
// Every mip level above 0 of a one-texel 0/255 checker is 128 (scene/mip_chain.hpp), so
// where lambda >= 1 the floor is exactly 128, and where 0 < lambda < 1 it is within
// 128 (1 - lambda) of it (level 0's bilinear value is in [0, 255]). Bilinear filtering,
// the control, strays far from 128 in the distance.
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include "effect_scenes.hpp"
#include "picture_check.hpp"

using namespace spanlight;
using namespace spanlight::effects;

namespace {

constexpr int checker_side = 64;

scene::Image one_texel_checker() {
  std::vector<int> values;
  for (int y = 0; y < checker_side; ++y)
    for (int x = 0; x < checker_side; ++x) values.push_back((x + y) % 2 == 0 ? 255 : 0);
  return grey_image(checker_side, checker_side, values);
}

// The floor y = 0 for x in [-50, 50], z in [-100, -0.5], uv = (x, -z) / 4, seen from 1 above,
// looking down ~27 degrees; nothing is near-clipped, so each triangle keeps its own vertices.
scene::Scene checker_floor(scene::Filter filter) {
  scene::Scene s = head_on_scene();
  s.camera = scene::Camera{{0, 1, 0}, {0, 0, -2}, {0, 1, 0}, 90, 0.05, 200};
  s.ambient = glm::dvec3(1.0);
  const int checker = add_texture(s, "checker", one_texel_checker(), filter, scene::Wrap::repeat);
  scene::Object floor;
  floor.name = "floor";
  floor.mesh.positions = {{-50, 0, -0.5}, {50, 0, -0.5}, {50, 0, -100}, {-50, 0, -100}};
  for (const glm::dvec3& p : floor.mesh.positions) floor.mesh.uvs.emplace_back(p.x / 4, -p.z / 4);
  floor.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  floor.texture = checker;
  s.objects.push_back(floor);
  return s;
}

// The exact rule at each pixel centre, worked out here from the spec: the triangle's
// vertices projected and snapped to 1/256 px, uv(p) = sum(b_i uv_i / w_i) / sum(b_i / w_i)
// with screen barycentrics b_i, lambda = log2 of the longer screen derivative of
// (u, v) * 64, the derivatives by central differences (h = 2^-12 px; along a line uv is a
// Moebius function, so the truncation error is h^2 |uv'| (D'/D)^2 with D = sum b_i / w_i:
// below 1e-6 |uv'| while the far edge, where D'/D is largest, lies over 0.2 px below the
// horizon). Error in lambda: well below reference_lambda_error. -inf off the floor.
constexpr double reference_lambda_error = 1e-4;

std::vector<double> exact_lambda(const scene::Scene& s) {
  const glm::dmat4 clip_from_object = scene::camera_view_projection(s);
  const scene::Mesh& mesh = s.objects[0].mesh;
  std::vector<glm::dvec2> window;
  std::vector<double> w;
  for (const glm::dvec3& p : mesh.positions) {
    const glm::dvec4 clip = clip_from_object * glm::dvec4(p, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    const glm::dvec2 px((ndc.x * 0.5 + 0.5) * side, (1.0 - (ndc.y * 0.5 + 0.5)) * side);
    window.push_back(glm::dvec2(std::llround(px.x * 256), std::llround(px.y * 256)) / 256.0);
    w.push_back(clip.w);
  }
  const auto cross = [](glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; };
  std::vector<double> lambda(side * side, -std::numeric_limits<double>::infinity());
  for (int y = 0; y < side; ++y) {
    for (int x = 0; x < side; ++x) {
      const glm::dvec2 centre(x + 0.5, y + 0.5);
      for (const auto& t : mesh.triangles) {
        const glm::dvec2 a = window[t[0]], b = window[t[1]], c = window[t[2]];
        const double area = cross(b - a, c - a);
        const auto bary = [&](glm::dvec2 p) {
          return glm::dvec3(cross(b - p, c - p), cross(c - p, a - p), cross(a - p, b - p)) / area;
        };
        const glm::dvec3 at_centre = bary(centre);
        if (at_centre.x < 0 || at_centre.y < 0 || at_centre.z < 0) continue;
        const auto uv = [&](glm::dvec2 p) {
          const glm::dvec3 l = bary(p);
          glm::dvec2 num(0.0);
          double den = 0.0;
          for (int i = 0; i < 3; ++i) {
            num += l[i] * mesh.uvs[t[static_cast<std::size_t>(i)]] / w[t[static_cast<std::size_t>(i)]];
            den += l[i] / w[t[static_cast<std::size_t>(i)]];
          }
          return num / den;
        };
        const double h = std::ldexp(1.0, -12);
        const glm::dvec2 dx = (uv(centre + glm::dvec2(h, 0)) - uv(centre - glm::dvec2(h, 0))) / (2 * h) * double(checker_side);
        const glm::dvec2 dy = (uv(centre + glm::dvec2(0, h)) - uv(centre - glm::dvec2(0, h))) / (2 * h) * double(checker_side);
        lambda[static_cast<std::size_t>(y * side + x)] = std::log2(std::max(glm::length(dx), glm::length(dy)));
        break;
      }
    }
  }
  return lambda;
}

}  // namespace

TEST_CASE("a one-texel checker is exactly 128 where lambda >= 1 and within 128 (1 - lambda) below", "[effects][mip]") {
  const scene::Scene trilinear = checker_floor(scene::Filter::trilinear);
  const std::vector<double> lambda = exact_lambda(trilinear);
  for (const EffectRenderer& renderer : effect_renderers()) {
    INFO(renderer.name);
    const double error = renderer.lambda_error + reference_lambda_error;
    const Picture picture = renderer.render(trilinear);
    int converged = 0, between = 0;
    const Mismatches m = compare_grey(picture, [&](int x, int y) {
      const double l = lambda[static_cast<std::size_t>(y * side + x)];
      if (l - error >= 1.0) {
        ++converged;
        return 128;
      }
      return -1;
    }, renderer.value_lsb);
    INFO(m.first);
    CHECK(m.count == 0);
    for (int y = 0; y < side; ++y) {
      for (int x = 0; x < side; ++x) {
        const double l = lambda[static_cast<std::size_t>(y * side + x)];
        if (!(l > error && l + error < 1.0)) continue;
        ++between;
        // |mix - 128| <= (1 - lambda) * 128, plus the byte's rounding and the renderer's bound.
        const double bound = 128.0 * (1.0 - l + error) + 0.5 + renderer.value_lsb;
        INFO("pixel " << x << ", " << y << " lambda " << l);
        CHECK(std::abs(picture.channel(x, y, 0) - 128) <= bound);
      }
    }
    CHECK(converged > 300);  // the distant floor
    CHECK(between > 20);     // the band where the mix crosses from level 0
  }
}

TEST_CASE("control: bilinear filtering of the same floor strays far from 128 in the distance", "[effects][mip]") {
  const scene::Scene bilinear = checker_floor(scene::Filter::bilinear);
  const std::vector<double> lambda = exact_lambda(bilinear);
  for (const EffectRenderer& renderer : effect_renderers()) {
    const Picture picture = renderer.render(bilinear);
    int far_off = 0;
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x)
        if (lambda[static_cast<std::size_t>(y * side + x)] >= 1.0 && std::abs(picture.channel(x, y, 0) - 128) > 64) ++far_off;
    INFO(renderer.name);
    CHECK(far_off > 20);
  }
}
