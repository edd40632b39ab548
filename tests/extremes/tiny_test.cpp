// Tiny and thin: sub-pixel triangles, slivers, a 64-slice fan of slivers, a
// sub-pixel fan whose slices all meet at one pixel centre, and meshes with
// huge coordinates (a floor grid and a fan 2e4 units across around the eye,
// whose triangles cross the near plane and the guard band).
//
// Two exact checks:
//  (1) for triangles wholly in view, the pixels the geometry walk covers are
//      exactly float_model::pixel_covered's on the pipeline's own snapped
//      vertices (setup + row walk implement the rule bit for bit);
//  (2) against the exact outline (the float model's near/far clip in double,
//      unsnapped): a pixel whose centre lies farther than `margin` from every
//      triangle's outline must be covered exactly as many times as there are
//      triangles around it (so 1 inside a watertight mesh, 0 outside). The
//      margin is derived per triangle (see vertex_error_px).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "../pipeline/eye_pass.hpp"
#include "../support/convex_polygon.hpp"
#include "extremes_support.hpp"
#include "float_model/clip.hpp"
#include "float_model/transform.hpp"

using namespace spanlight::xt;
using spanlight::ScreenVertex;
using spanlight::test_support::inside_distance;

namespace {

// ---- the fixed pipeline's coverage ----------------------------------------------------------

// How many times the eye pass's geometry walk covers each pixel (no depth test).
std::vector<int> coverage_counts(const pr::PreparedStorage& prepared) {
  bool outside = false;
  std::vector<int> counts = spanlight::ptest::eye_coverage_counts(prepared.scene, prepared.matrices, &outside);
  REQUIRE_FALSE(outside);
  return counts;
}

// ---- check (1): the rule on the pipeline's own snapped vertices -------------------------------

int rule_mismatches(const pr::PreparedStorage& prepared) {
  const spanlight::PreparedScene& scene = prepared.scene;
  const std::vector<int> counts = coverage_counts(prepared);
  std::vector<int> reference(counts.size(), 0);
  for (std::uint16_t o = 0; o < scene.object_count; ++o) {
    const spanlight::ObjectData& object = scene.objects[o];
    for (std::uint32_t tri = 0; tri < object.triangle_count; ++tri) {
      fm::SnappedVertex v[3];
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t index = object.indices[tri * 3 + k];
        const ScreenVertex sv = spanlight::ptest::eye_screen_vertex(scene, prepared.matrices, o, index);
        v[k] = {sv.x, sv.y};
      }
      for (const auto& [x, y] : fm::covered_pixels(v, scene.width, scene.height))
        ++reference[static_cast<std::size_t>(y * scene.width + x)];
    }
  }
  int mismatches = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) mismatches += counts[i] != reference[i];
  return mismatches;
}

// ---- check (2): against the exact outline -------------------------------------------------------

struct ExactTriangle {
  std::vector<glm::dvec2> outline;  // window coordinates (px, y down) of the near/far-clipped polygon
  double margin;                    // px
};

// How far (px) the fixed pipeline may put a point of this triangle's outline:
//  - snapping: 1/512 px, after a divide good to 2^-7 subpixel (project.hpp);
//  - the clip matrix, block floating point with one exponent (vec.hpp): its
//    entries are off by up to 2^-(frac_bits+1), so a clip coordinate by
//    e <= sum |dm| |p| + 2^-33 (the transform's own rounding). A point of the
//    clipped polygon interpolates its edge's endpoints, so its error is at most
//    the larger endpoint error; its window position x/w moves by at most
//    (e_x + |x/w| e_w) / w <= e (1 + G) / w_min NDC, w_min its smallest w.
// The margin is twice the sum, for the two endpoints of an edge.
double vertex_error_px(const sc::Scene& s, const sc::Object& o, const std::array<std::uint32_t, 3>& tri,
                       const spanlight::Mat4Block& fixed, double w_min) {
  const glm::dmat4 exact = sc::camera_view_projection(s) * o.model;
  double e = 0;
  for (const std::uint32_t index : tri) {
    const glm::dvec4 p(o.mesh.positions[index], 1.0);
    for (int row : {0, 1, 3}) {
      double err = std::ldexp(1.0, -33);
      for (int col = 0; col < 4; ++col)
        err += std::fabs(fixedpoint::mat4_block_entry(fixed, col, row) - exact[col][row]) * std::fabs(p[col]);
      e = std::max(e, err);
    }
  }
  const double guard = static_cast<double>(spanlight::guard_band(s.width, s.height));
  const double ndc = e * (1.0 + guard) / w_min;
  return 1.0 / 512.0 + std::ldexp(1.0, -15) + ndc * std::max(s.width, s.height) / 2.0;
}

std::vector<ExactTriangle> exact_triangles(const sc::Scene& s, const pr::PreparedStorage& prepared) {
  std::vector<ExactTriangle> out;
  for (std::size_t oi = 0; oi < s.objects.size(); ++oi) {
    const sc::Object& o = s.objects[oi];
    const fm::ObjectTransform transform = fm::eye_transform(s, o);
    for (std::size_t t = 0; t < o.mesh.triangles.size(); ++t) {
      const fm::ClipTriangle tri = fm::transform_triangle(transform, o.mesh, t);
      std::vector<fm::ClipVertex> poly(tri.begin(), tri.end());
      poly = fm::clip_polygon(poly, fm::ClipPlane::near);
      poly = fm::clip_polygon(poly, fm::ClipPlane::far);
      if (poly.size() < 3) continue;
      ExactTriangle e;
      double w_min = 1e300;
      for (const fm::ClipVertex& v : poly) {
        const fm::WindowPoint p = fm::to_window(v.position, s.width, s.height);
        e.outline.emplace_back(p.x, p.y);
        w_min = std::min(w_min, v.position.w);
      }
      e.margin = 2.0 * vertex_error_px(s, o, o.mesh.triangles[t], prepared.clip_from_object[oi], w_min);
      out.push_back(std::move(e));
    }
  }
  return out;
}

struct OutlineCheck {
  int certain = 0;      // pixels farther than the margin from every outline
  int wrong = 0;        // of those, covered a different number of times than expected
  int inside_once = 0;  // certain pixels inside exactly one triangle
  int max_count = 0;
  double largest_margin = 0;
};

OutlineCheck check_outline(const sc::Scene& s, const pr::PreparedStorage& prepared) {
  const std::vector<int> counts = coverage_counts(prepared);
  const std::vector<ExactTriangle> triangles = exact_triangles(s, prepared);
  OutlineCheck r;
  for (const ExactTriangle& t : triangles) r.largest_margin = std::max(r.largest_margin, t.margin);
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      const glm::dvec2 centre(x + 0.5, y + 0.5);
      int expected = 0;
      bool certain = true;
      for (const ExactTriangle& t : triangles) {
        const double d = inside_distance(t.outline, centre);
        if (std::fabs(d) <= t.margin) {
          certain = false;
          break;
        }
        expected += d > 0;
      }
      const int got = counts[static_cast<std::size_t>(y * s.width + x)];
      r.max_count = std::max(r.max_count, got);
      if (!certain) continue;
      ++r.certain;
      r.inside_once += expected == 1;
      r.wrong += got != expected;
    }
  return r;
}

// ---- scenes ----------------------------------------------------------------------------------------

// The camera looks down -z at the plane z = 0 from z = 10; one pixel is
// `px` units there. Returns the world point of window position (x, y) (px, y down).
struct FacingView {
  sc::Scene scene;
  double px;
  glm::dvec3 at(double x, double y) const {
    return {(x - scene.width / 2.0) * px, (scene.height / 2.0 - y) * px, 0.0};
  }
};

FacingView facing(int width, int height) {
  const double distance = 10.0, px = 1.0 / 32.0;  // 1/32 unit per pixel: Q15.16 positions are 1/2048 px apart
  const double fovy = 2.0 * std::atan(height / 2.0 * px / distance) * 180.0 / std::numbers::pi;
  FacingView v{make_scene(width, height, {0, 0, distance}, {0, 0, 0}, {0, 1, 0}, fovy, 1.0, 30.0), px};
  v.scene.ambient = glm::dvec3(0.5);
  return v;
}

sc::Object mesh_object(const std::string& name, std::vector<glm::dvec3> positions,
                       std::vector<std::array<std::uint32_t, 3>> triangles) {
  sc::Object o;
  o.name = name;
  o.mesh.positions = std::move(positions);
  o.mesh.uvs.assign(o.mesh.positions.size(), glm::dvec2(0.0));
  o.mesh.triangles = std::move(triangles);
  return o;
}

// A fan of `slices` triangles around `centre` (window px) between angles a0 and a1 (a full
// circle when a1 - a0 = 2 pi), radius r px; alternate slices wound the other way.
sc::Object fan(const FacingView& view, glm::dvec2 centre, double radius, double a0, double a1, int slices) {
  std::vector<glm::dvec3> positions{view.at(centre.x, centre.y)};
  const bool closed = std::fabs(a1 - a0 - 2.0 * std::numbers::pi) < 1e-12;
  const int rim = closed ? slices : slices + 1;
  for (int k = 0; k < rim; ++k) {
    const double a = a0 + (a1 - a0) * k / slices;
    positions.push_back(view.at(centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)));
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (int k = 0; k < slices; ++k) {
    const auto a = static_cast<std::uint32_t>(1 + k), b = static_cast<std::uint32_t>(1 + (k + 1) % rim);
    triangles.push_back(k % 2 == 0 ? std::array<std::uint32_t, 3>{0, a, b} : std::array<std::uint32_t, 3>{0, b, a});
  }
  return mesh_object("fan", positions, triangles);
}

}  // namespace

TEST_CASE("sub-pixel triangles cover exactly the pixels the rule gives, and no others", "[extremes][tiny]") {
  FacingView view = facing(64, 48);
  std::mt19937_64 rng(0x71a1);
  std::uniform_real_distribution<double> where(-1.0, 65.0), size(0.01, 1.5), angle(0.0, 2.0 * std::numbers::pi);
  std::vector<glm::dvec3> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (std::uint32_t n = 0; n < 600; ++n) {
    const glm::dvec2 c(where(rng), where(rng) * 0.75);
    for (int k = 0; k < 3; ++k) {
      const double a = angle(rng), r = size(rng);
      positions.push_back(view.at(c.x + r * std::cos(a), c.y + r * std::sin(a)));
    }
    triangles.push_back({3 * n, 3 * n + 1, 3 * n + 2});
  }
  // Every 5th triangle centred exactly on a pixel centre or corner: ties.
  for (std::uint32_t n = 0; n < 600; n += 5) {
    const glm::dvec3 c = view.at(std::floor(where(rng)) + (n % 2 ? 0.5 : 0.0), std::floor(where(rng) * 0.75) + 0.5);
    positions[3 * n] = c + glm::dvec3(0.5 * view.px, 0, 0);
    positions[3 * n + 1] = c + glm::dvec3(-0.5 * view.px, 0.5 * view.px, 0);
    positions[3 * n + 2] = c + glm::dvec3(-0.5 * view.px, -0.5 * view.px, 0);
  }
  view.scene.objects.push_back(mesh_object("specks", positions, triangles));
  snap_positions_to_q16(view.scene);
  const auto prepared = pr::prepare_scene(view.scene);
  CHECK(rule_mismatches(*prepared) == 0);
  const OutlineCheck r = check_outline(view.scene, *prepared);
  INFO("certain pixels " << r.certain << ", wrong " << r.wrong << ", inside one triangle " << r.inside_once
                         << ", largest margin " << r.largest_margin << " px");
  CHECK(r.wrong == 0);
  CHECK(r.inside_once > 50);
  // Against the float model's whole render: same coverage up to outline pixels.
  const Both b = render_both(view.scene);
  const Agreement a = agree(b, 1, 3);
  INFO(describe(a, view.scene.width));
  CHECK(a.unexplained == 0);
}

TEST_CASE("slivers: long triangles far thinner than a pixel", "[extremes][tiny]") {
  // Short ones (<= 300 px) stay inside the guard band (+-6 w: 336 px here), so
  // the pipeline draws them unclipped and check (1) applies; long ones (up to
  // 3000 px) are cut by the guard band and checked against their outline.
  for (const double longest : {300.0, 3000.0}) {
    FacingView view = facing(96, 72);
    std::mt19937_64 rng(0x5117);
    std::uniform_real_distribution<double> where(0.0, 96.0), length(5.0, longest), width(1e-3, 0.4),
        angle(0.0, std::numbers::pi);
    std::vector<glm::dvec3> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (std::uint32_t n = 0; n < 300; ++n) {
      const glm::dvec2 c(where(rng), where(rng) * 0.75);
      const double a = n % 10 == 0 ? std::numbers::pi / 2 * (n % 20 == 0) : angle(rng);  // some axis-aligned
      const glm::dvec2 d(std::cos(a), std::sin(a)), normal(-d.y, d.x);
      const double half = length(rng) / 2, w = width(rng);
      // A sliver: two far points and one a hair off the line through them.
      positions.push_back(view.at(c.x - half * d.x, c.y - half * d.y));
      positions.push_back(view.at(c.x + half * d.x, c.y + half * d.y));
      positions.push_back(view.at(c.x + w * normal.x, c.y + w * normal.y));
      triangles.push_back({3 * n, 3 * n + 1, 3 * n + 2});
    }
    view.scene.objects.push_back(mesh_object("slivers", positions, triangles));
    snap_positions_to_q16(view.scene);
    const auto prepared = pr::prepare_scene(view.scene);
    if (longest <= 300.0) CHECK(rule_mismatches(*prepared) == 0);
    const OutlineCheck r = check_outline(view.scene, *prepared);
    INFO("up to " << longest << " px: certain pixels " << r.certain << ", wrong " << r.wrong << ", largest margin "
                  << r.largest_margin << " px");
    CHECK(r.wrong == 0);
    CHECK(r.certain > 5000);
  }
}

TEST_CASE("fans of slivers and of sub-pixel slices are watertight", "[extremes][tiny]") {
  SECTION("64 slices within 2 degrees, 4000 px long: each slice narrower than a pixel over most of its length") {
    FacingView view = facing(128, 96);
    const double a0 = 0.3, a1 = a0 + 2.0 * std::numbers::pi / 180.0;
    view.scene.objects.push_back(fan(view, {-30.25, 10.5}, 4000.0, a0, a1, 64));
    snap_positions_to_q16(view.scene);
    const auto prepared = pr::prepare_scene(view.scene);
    const OutlineCheck r = check_outline(view.scene, *prepared);
    INFO("certain pixels " << r.certain << ", wrong " << r.wrong << ", max count " << r.max_count << ", covered once "
                           << r.inside_once << ", largest margin " << r.largest_margin << " px");
    CHECK(r.max_count == 1);
    CHECK(r.wrong == 0);
    CHECK(r.inside_once > 100);
  }
  SECTION("64 slices of a 0.75 px disc, all meeting at a pixel centre: that pixel is covered exactly once") {
    for (const glm::dvec2 centre : {glm::dvec2(8.5, 6.5), glm::dvec2(8.0, 6.0), glm::dvec2(8.5, 6.0)}) {
      FacingView view = facing(16, 12);
      view.scene.objects.push_back(fan(view, centre, 0.75, 0.0, 2.0 * std::numbers::pi, 64));
      snap_positions_to_q16(view.scene);
      const auto prepared = pr::prepare_scene(view.scene);
      CHECK(rule_mismatches(*prepared) == 0);
      const std::vector<int> counts = coverage_counts(*prepared);
      int total = 0, most = 0;
      for (const int c : counts) {
        total += c;
        most = std::max(most, c);
      }
      INFO("centre " << centre.x << ", " << centre.y << ": " << total << " covered pixels");
      CHECK(most == 1);
      if (centre.x == 8.5 && centre.y == 6.5) CHECK(counts[6 * 16 + 8] == 1);  // the shared vertex is a pixel centre
    }
  }
}

TEST_CASE("huge coordinates: a jittered floor grid and a fan 2e4 units across around the eye are watertight",
          "[extremes][tiny][huge]") {
  // The camera is 1 unit above the floor and looks steeply down, so the floor
  // fills the picture: every pixel must be covered exactly once. Triangles are
  // up to 2500 units long: they cross the near plane behind the eye and leave
  // the guard band on several sides.
  for (const int variant : {0, 1}) {
    sc::Scene s = make_scene(96, 72, {0.3, 1.0, 0.2}, {1.0, -2.0, -1.5}, {0, 1, 0}, 75.0, 0.01, 30000.0);
    s.ambient = glm::dvec3(0.5);
    std::mt19937_64 rng(0x6e1d + static_cast<unsigned>(variant));
    if (variant == 0) {
      const int cells = 8;
      const double extent = 9999.0, cell = 2.0 * extent / cells;
      std::uniform_real_distribution<double> jitter(-0.3 * cell, 0.3 * cell);
      std::vector<glm::dvec3> positions;
      for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i) {
          const bool interior = i > 0 && i < cells && j > 0 && j < cells;
          positions.emplace_back(-extent + i * cell + (interior ? jitter(rng) : 0.0), 0.0,
                                 -extent + j * cell + (interior ? jitter(rng) : 0.0));
        }
      std::vector<std::array<std::uint32_t, 3>> triangles;
      auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (cells + 1) + i); };
      for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) {
          const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
          if ((i + j) % 2 == 0) {
            triangles.push_back({a, b, c});
            triangles.push_back({a, d, c});  // the other winding
          } else {
            triangles.push_back({a, b, d});
            triangles.push_back({b, c, d});
          }
        }
      s.objects.push_back(mesh_object("grid", positions, triangles));
    } else {
      // 64 slices around a centre just beside the eye's foot point, radius 1e4.
      std::vector<glm::dvec3> positions{{0.37, 0.0, 0.11}};
      for (int k = 0; k < 64; ++k) {
        const double a = 0.01 + 2.0 * std::numbers::pi * k / 64;
        positions.emplace_back(0.37 + 9990.0 * std::cos(a), 0.0, 0.11 + 9990.0 * std::sin(a));
      }
      std::vector<std::array<std::uint32_t, 3>> triangles;
      for (std::uint32_t k = 0; k < 64; ++k) {
        const std::uint32_t a = 1 + k, b = 1 + (k + 1) % 64;
        triangles.push_back(k % 2 ? std::array<std::uint32_t, 3>{0, a, b} : std::array<std::uint32_t, 3>{0, b, a});
      }
      s.objects.push_back(mesh_object("big_fan", positions, triangles));
    }
    snap_positions_to_q16(s);
    const auto prepared = pr::prepare_scene(s);
    const std::vector<int> counts = coverage_counts(*prepared);
    int not_once = 0;
    for (const int c : counts) not_once += c != 1;
    const OutlineCheck r = check_outline(s, *prepared);
    INFO("variant " << variant << ": pixels not covered exactly once " << not_once << "; certain " << r.certain
                    << ", wrong " << r.wrong << ", largest margin " << r.largest_margin << " px");
    CHECK(not_once == 0);
    CHECK(r.wrong == 0);
  }
}
