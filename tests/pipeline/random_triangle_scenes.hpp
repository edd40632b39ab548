// Seeded random one-triangle scenes for the attribute property test: every
// kind of triangle the pipeline must interpolate on (general, large, tiny,
// slivers, collinear and repeated vertices, axis-aligned on the pixel-centre
// lattice), each vertex at its own w between the near and far planes (up to
// 2 * 10^4 apart: strong perspective), random uv, and two projectors placed
// at random with q > 0 at all three vertices. Vertices stay strictly inside
// near/far and within +-4.5 in NDC x and y (the guard band is +-6 w here), so
// neither renderer clips: both interpolate the very same triangle.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline_support.hpp"

namespace spanlight::ptest {

struct RandomTriangles {
  static constexpr int width = 96, height = 64;
  static constexpr double fovy_deg = 60.0, near = 0.1, far = 2000.0;
  // 1 % inside the planes: Q15.16 positions move a vertex by 2^-17 units, far less.
  static constexpr double w_lo = near * 1.01, w_hi = far * 0.99;
  static constexpr int surface_texels = 64;                         // the object's 64x64 texture
  static constexpr std::array<std::array<int, 2>, 2> projector_images{{{64, 64}, {256, 16}}};

  // B * P_j * V_j * M has entries of about (cot(fov/2) / aspect + 1) / 2 * |eye - centre| (the
  // object's origin is its centre): 1000 keeps them below prepare's 2^13 for fov >= 20, aspect >= 1/2.
  static constexpr double max_projector_distance = 1000.0;

  std::mt19937 rng;

  explicit RandomTriangles(std::uint32_t seed) : rng(seed) {}

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  int pick(int count) { return std::uniform_int_distribution<int>(0, count - 1)(rng); }

  // A point of the camera's eye space (the camera sits at the origin looking down -z) from its
  // NDC x, y and its w (= -z).
  static glm::dvec3 eye_point(double x_ndc, double y_ndc, double w) {
    const double tan_half = std::tan(fovy_deg * std::numbers::pi / 360.0);
    const double aspect = static_cast<double>(width) / height;
    return {x_ndc * w * tan_half * aspect, y_ndc * w * tan_half, -w};
  }

  std::array<double, 3> vertex_ws() {
    std::array<double, 3> w{};
    switch (pick(4)) {
      case 0:  // each anywhere between the planes: up to 2 * 10^4 apart
        for (double& x : w) x = log_uniform(w_lo, w_hi);
        break;
      case 1: {  // one vertex at the near plane, the others far behind it
        w = {log_uniform(w_lo, 2 * w_lo), log_uniform(w_hi / 10, w_hi), log_uniform(w_hi / 10, w_hi)};
        std::shuffle(w.begin(), w.end(), rng);
        break;
      }
      case 2: {  // nearly equal: almost affine
        const double base = log_uniform(w_lo * 1.01, w_hi / 1.01);
        for (double& x : w) x = base * uniform(0.99, 1.01);
        break;
      }
      default:  // exactly equal: affine
        w.fill(log_uniform(w_lo, w_hi));
    }
    return w;
  }

  // NDC x, y of the three vertices, by kind of triangle.
  std::array<glm::dvec2, 3> screen_shape() {
    const glm::dvec2 px_ndc(2.0 / width, 2.0 / height);  // one pixel in NDC
    auto anywhere = [&](double r) { return glm::dvec2(uniform(-r, r), uniform(-r, r)); };
    std::array<glm::dvec2, 3> p{anywhere(1.5), anywhere(1.5), anywhere(1.5)};
    switch (pick(8)) {
      case 0:
      case 1: break;  // general
      case 2: p = {anywhere(3.0), anywhere(3.0), anywhere(3.0)}; break;  // large, often the whole viewport
      case 3: {  // tiny: a few pixels down to a hundredth of one
        const double size = log_uniform(0.01, 4.0);
        for (int k = 1; k < 3; ++k) p[k] = p[0] + glm::dvec2(uniform(-size, size), uniform(-size, size)) * px_ndc;
        break;
      }
      case 4: {  // sliver: c a few subpixels off the line a-b
        const glm::dvec2 d = p[1] - p[0];
        const glm::dvec2 normal = glm::dvec2(-d.y, d.x) / std::max(glm::length(d / px_ndc), 1e-9);
        p[2] = 0.5 * (p[0] + p[1]) + normal * uniform(-4.0, 4.0) / 256.0;
        break;
      }
      case 5: p[2] = p[0] + uniform(-1.0, 2.0) * (p[1] - p[0]); break;  // collinear before snapping
      case 6: p[2] = p[pick(2)]; break;                                     // a repeated screen position
      default: {  // axis-aligned right triangle on the pixel-centre lattice: centres on both legs
        const glm::dvec2 corner = glm::round(p[0] / px_ndc) * px_ndc + 0.5 * px_ndc;
        p = {corner, corner + glm::dvec2(pick(41) - 20, 0) * px_ndc, corner + glm::dvec2(0, pick(41) - 20) * px_ndc};
      }
    }
    return p;
  }

  // A projector looking at the triangle from anywhere (with q > 0 at every vertex), or, when
  // 50 draws miss, from along its normal, where q is the distance to the triangle's plane.
  scene::Projector random_projector(const std::array<glm::dvec3, 3>& v, int image) {
    const glm::dvec3 centre = (v[0] + v[1] + v[2]) / 3.0;
    const double size = std::max({glm::length(v[1] - v[0]), glm::length(v[2] - v[0]), 1e-3});
    auto direction = [&] {
      const glm::dvec3 d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      return glm::length(d) > 1e-3 ? glm::normalize(d) : glm::dvec3(0, 0, 1);
    };
    for (int attempt = 0; attempt < 50; ++attempt) {
      const double distance = std::min(size * log_uniform(0.05, 100.0), max_projector_distance);
      const glm::dvec3 eye = centre + direction() * distance;
      const glm::dvec3 target = centre + direction() * size * uniform(0.0, 1.0);
      glm::dvec3 up = direction();
      if (glm::length(glm::cross(up, target - eye)) < 1e-6 * glm::length(target - eye)) continue;
      scene::Projector p = projector(eye, target, up, uniform(20.0, 170.0), distance * 1e-3, distance * 1e3, image,
                                     glm::dvec3(1.0));
      p.aspect = log_uniform(0.5, 2.0);
      const glm::dmat4 m = scene::projector_texture_matrix(scene::Camera{}, p);  // a world-space projector: no camera
      if (std::all_of(v.begin(), v.end(), [&](const glm::dvec3& x) { return (m * glm::dvec4(x, 1.0)).w > 0.0; }))
        return p;
    }
    glm::dvec3 normal = glm::cross(v[1] - v[0], v[2] - v[0]);
    normal = glm::length(normal) > 0.0 ? glm::normalize(normal) : glm::dvec3(0, 0, 1);
    const glm::dvec3 up = std::fabs(normal.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    const double distance = std::min(size * 2.0, max_projector_distance);
    return projector(centre + normal * distance, centre, up, 90.0, distance * 1e-3, distance * 1e3, image,
                     glm::dvec3(1.0));
  }

  scene::Scene next() {
    scene::Scene s = empty_scene(width, height, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, fovy_deg, near, far);
    s.textures.push_back(texture("surface", solid_image(surface_texels, surface_texels, {200, 200, 200}),
                                 scene::Filter::nearest, scene::Wrap::repeat));
    for (const auto& [w, h] : projector_images)
      s.textures.push_back(texture("slide", solid_image(w, h, {255, 255, 255}), scene::Filter::nearest, scene::Wrap::border));

    const std::array<glm::dvec2, 3> ndc = screen_shape();
    const std::array<double, 3> w = vertex_ws();
    scene::Object o;
    o.name = "triangle";
    o.texture = 0;
    const double uv_range = log_uniform(1.0, 1024.0) / surface_texels;  // up to +-1024 texels
    const std::array<glm::dvec3, 3> v{eye_point(ndc[0].x, ndc[0].y, w[0]), eye_point(ndc[1].x, ndc[1].y, w[1]),
                                      eye_point(ndc[2].x, ndc[2].y, w[2])};
    // Positions relative to the centre, which the model matrix adds back, so that a projector's
    // matrix translates by about its distance to the triangle, not to the camera.
    const glm::dvec3 centre = (v[0] + v[1] + v[2]) / 3.0;
    o.model = glm::translate(glm::dmat4(1.0), centre);
    for (int k = 0; k < 3; ++k) {
      o.mesh.positions.push_back(v[k] - centre);
      o.mesh.uvs.emplace_back(uniform(-uv_range, uv_range), uniform(-uv_range, uv_range));
    }
    o.mesh.triangles = {{0, 1, 2}};
    s.objects.push_back(o);
    for (int j = 0; j < static_cast<int>(projector_images.size()); ++j) s.projectors.push_back(random_projector(v, 1 + j));
    return s;
  }
};

}  // namespace spanlight::ptest
