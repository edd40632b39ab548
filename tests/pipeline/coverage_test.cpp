// Watertightness and the exact coverage rule of the fixed pipeline.
//
// (a), (b): meshes whose triangles share edges (a closed 64-slice fan and an
// irregular 13 x 9 grid) go through the whole geometry walk (transform, clip,
// project, setup, rows); a counting kernel with no depth test sees every
// covered pixel, so a pixel two triangles both cover shows up as a 2.
// (c): setup_triangle + rasterize_rows on random snapped triangles give the
// pixel set float_model::pixel_covered defines, pixel for pixel, and so does
// the small-triangle setup (setup_small) wherever it takes a triangle.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "float_model/float_model.hpp"
#include "pipeline_support.hpp"
#include "../support/convex_polygon.hpp"

namespace fm = spanlight::float_model;
namespace pt = spanlight::ptest;
using spanlight::Cull;
using spanlight::ScreenVertex;
using spanlight::test_support::inside_distance;

namespace {

// Window position (pixels, y down) of a world point, in double: the exact
// value the pipeline's snapped vertex approximates.
glm::dvec2 exact_window(const spanlight::scene::Scene& s, glm::dvec3 p) {
  const glm::dvec4 c = spanlight::scene::camera_view_projection(s) * glm::dvec4(p, 1.0);
  return {(c.x / c.w * 0.5 + 0.5) * s.width, (0.5 - c.y / c.w * 0.5) * s.height};
}

fm::SnappedVertex snapped(const ScreenVertex& v) { return {v.x, v.y}; }

// Per-pixel count of how many of the object's triangles float_model's rule
// says cover the pixel, on the pipeline's own snapped vertices.
std::vector<int> reference_counts(const spanlight::prepare::PreparedStorage& prepared, std::uint16_t o) {
  const spanlight::PreparedScene& scene = prepared.scene;
  const spanlight::ObjectData& object = scene.objects[o];
  std::vector<int> counts(std::size_t{scene.width} * scene.height, 0);
  for (std::uint32_t tri = 0; tri < object.triangle_count; ++tri) {
    fm::SnappedVertex v[3];
    for (std::uint32_t k = 0; k < 3; ++k)
      v[k] = snapped(pt::eye_screen_vertex(scene, prepared.matrices, o, object.indices[tri * 3 + k]));
    for (const auto& [x, y] : fm::covered_pixels(v, scene.width, scene.height))
      ++counts[static_cast<std::size_t>(y * scene.width + x)];
  }
  return counts;
}

// How far a snapped vertex may lie from the exact window position of the
// scene's (double) vertex: prepare rounds positions to Q15.16 (<= 2^-17 world
// units per coordinate; with the camera looking straight down -z, screen x
// depends on world x alone, so <= 2^-17 * px_per_unit pixels); the matrix
// keeps 28 significant bits and the divide is good to 2^-7 subpixel
// (project.hpp), together far below 2^-12 px; snapping rounds to the nearest
// 1/256 px (<= 1/512 px).
double vertex_tolerance_px(double px_per_unit) { return 1.0 / 512.0 + px_per_unit / 131072.0 + 1.0 / 4096.0; }

// The mesh's properties that do not depend on its shape:
//  - every pixel is covered at most once (no double hits on shared edges);
//  - pixels clearly inside the outline are covered exactly once, clearly
//    outside never (no cracks, no spill);
//  - the counts equal float_model's rule applied to the same snapped vertices;
//  - rendered with one projector, each light pass touches a pixel at most
//    once, every visible pixel exactly once, and the light is added once.
// Pixel centres farther than twice the vertex tolerance from the exact
// outline are certainly inside (or outside) the snapped mesh's outline, since
// every point of an edge moves no more than its end points do.
void check_watertight(const spanlight::scene::Scene& s, const std::vector<glm::dvec2>& outline, double px_per_unit) {
  const double tolerance = vertex_tolerance_px(px_per_unit);
  const double outline_margin_px = 2.0 * tolerance;
  const auto prepared = spanlight::prepare::prepare_scene(s);
  const spanlight::PreparedScene& scene = prepared->scene;
  bool outside = false;
  const std::vector<int> counts = pt::eye_coverage_counts(scene, prepared->matrices, &outside);
  const std::vector<int> reference = reference_counts(*prepared, 0);
  CHECK_FALSE(outside);
  // The same scene without its projector lets the eye pass take the small-triangle
  // path (draw.hpp: small_path_allowed): its 32-bit edges must cover the same pixels.
  spanlight::PreparedScene no_projector = scene;
  no_projector.projector_count = 0;
  const std::vector<int> small_counts = pt::eye_coverage_counts(no_projector, prepared->matrices, &outside);
  CHECK_FALSE(outside);
  CHECK(small_counts == reference);

  // The snapped vertices are where the exact projection puts them (this is
  // what makes the outline margin above valid).
  for (std::uint32_t i = 0; i < s.objects[0].mesh.positions.size(); ++i) {
    const ScreenVertex v = pt::eye_screen_vertex(scene, prepared->matrices, 0, i);
    const glm::dvec2 exact = exact_window(s, s.objects[0].mesh.positions[i]);
    REQUIRE(std::fabs(v.x / 256.0 - exact.x) <= tolerance);
    REQUIRE(std::fabs(v.y / 256.0 - exact.y) <= tolerance);
  }

  int inside = 0, doubles = 0, cracks = 0, spills = 0, mismatches = 0;
  for (int y = 0; y < s.height; ++y) {
    for (int x = 0; x < s.width; ++x) {
      const auto i = static_cast<std::size_t>(y * s.width + x);
      const double d = inside_distance(outline, glm::dvec2(x + 0.5, y + 0.5));
      if (counts[i] > 1) ++doubles;
      if (d > outline_margin_px) {
        ++inside;
        if (counts[i] != 1) ++cracks;
      }
      if (d < -outline_margin_px && counts[i] != 0) ++spills;
      if (counts[i] != reference[i]) ++mismatches;
    }
  }
  INFO("pixels inside the outline: " << inside);
  CHECK(inside > 1000);  // the property is not vacuous
  CHECK(doubles == 0);
  CHECK(cracks == 0);
  CHECK(spills == 0);
  CHECK(mismatches == 0);

  // Multipass with one projector that covers everything: the light pass.
  const spanlight::Knobs knobs = pt::knobs_with(spanlight::Passes::multipass);
  const pt::ObservedFrame frame = pt::render_observed(*prepared, knobs);
  std::vector<int> light_touches(counts.size(), 0);
  for (const pt::PassEvent& e : frame.log.events)
    if (e.pass == spanlight::Pass::light) ++light_touches[e.index];
  const std::uint32_t clear = spanlight::depth_clear(knobs.depth_bits);
  int wrong_touches = 0, wrong_colour = 0, visible = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const bool is_visible = frame.depth[i] != clear;
    visible += is_visible;
    if (light_touches[i] != (is_visible ? 1 : 0)) ++wrong_touches;
    // ambient 0.2 -> 51 levels; projector colour 0.3 -> Q8.8 77, times the
    // white texel: round(77 * 255 / 256) = 77 levels; 51 + 77 = 128, times a
    // white surface stays 128. Light added twice would give 205.
    const std::uint8_t expected = is_visible ? 128 : 0;
    for (int c = 0; c < 3; ++c) wrong_colour += frame.rgb[i * 3 + static_cast<std::size_t>(c)] != expected;
  }
  int covered = 0;
  for (const int c : counts) covered += c > 0;
  INFO("visible pixels: " << visible);
  CHECK(visible == covered);  // the depth pass kept every covered pixel
  CHECK(wrong_touches == 0);
  CHECK(wrong_colour == 0);
}

// Camera straight down -z at a plane z = 0; a projector from the same spot
// with a wider frustum lights the whole plane with a white 1x1 image.
spanlight::scene::Scene facing_scene(int width, int height, double half_height_world) {
  const double distance = 10.0;
  const double fovy = 2.0 * std::atan(half_height_world / distance) * 180.0 / std::numbers::pi;
  auto s = pt::empty_scene(width, height, {0, 0, distance}, {0, 0, 0}, {0, 1, 0}, fovy, 1.0, 30.0);
  s.ambient = glm::dvec3(0.2);
  s.textures.push_back(pt::texture("white", pt::solid_image(1, 1, {255, 255, 255}), spanlight::scene::Filter::nearest,
                                   spanlight::scene::Wrap::clamp));
  s.projectors.push_back(pt::projector({0, 0, distance}, {0, 0, 0}, {0, 1, 0}, fovy + 20.0, 1.0, 30.0, 0,
                                       glm::dvec3(0.3)));
  return s;
}

}  // namespace

TEST_CASE("a closed 64-slice fan is covered exactly once inside and never twice, light added once", "[coverage]") {
  const int slices = 64;
  // Centres at odd positions (one on the axis, so many slices tie at a pixel
  // centre); alternate slices are listed in opposite windings.
  for (const glm::dvec2 middle : {glm::dvec2(0.0, 0.0), glm::dvec2(0.01234, -0.00711), glm::dvec2(-0.0371, 0.0219)}) {
    for (const double phase : {0.0, 0.0137}) {
      auto s = facing_scene(96, 80, 1.2);
      spanlight::scene::Object fan;
      fan.name = "fan";
      fan.mesh.positions.push_back({middle.x, middle.y, 0.0});
      std::vector<glm::dvec2> outline;
      for (int k = 0; k < slices; ++k) {
        const double angle = phase + 2.0 * std::numbers::pi * k / slices;
        const glm::dvec3 rim{middle.x + std::cos(angle), middle.y + std::sin(angle), 0.0};
        fan.mesh.positions.push_back(rim);
        outline.push_back(exact_window(s, rim));
      }
      fan.mesh.uvs.assign(fan.mesh.positions.size(), glm::dvec2(0.0));
      for (std::uint32_t k = 0; k < slices; ++k) {
        const std::uint32_t a = 1 + k, b = 1 + (k + 1) % slices;
        fan.mesh.triangles.push_back(k % 2 == 0 ? std::array<std::uint32_t, 3>{0, a, b}
                                                : std::array<std::uint32_t, 3>{0, b, a});
      }
      s.objects.push_back(fan);
      INFO("middle " << middle.x << ", " << middle.y << " phase " << phase);
      check_watertight(s, outline, 80 / (2 * 1.2));
    }
  }
}

TEST_CASE("an irregular 13x9 triangle grid is covered exactly once inside and never twice, light added once",
          "[coverage]") {
  const int columns = 13, rows = 9;
  std::mt19937_64 rng(0x5eed0001);
  std::uniform_real_distribution<double> jitter(-0.25, 0.25);
  for (int variant = 0; variant < 3; ++variant) {
    auto s = facing_scene(128, 96, 1.0);
    const double angle = 0.35 + 0.2 * variant;  // rotated: no edge is axis-aligned
    const double cell_w = 1.6 / columns, cell_h = 1.1 / rows;
    auto place = [&](double gx, double gy) {
      const double x = (gx - columns / 2.0) * cell_w, y = (gy - rows / 2.0) * cell_h;
      return glm::dvec3(x * std::cos(angle) - y * std::sin(angle), x * std::sin(angle) + y * std::cos(angle), 0.0);
    };
    spanlight::scene::Object grid;
    grid.name = "grid";
    for (int j = 0; j <= rows; ++j) {
      for (int i = 0; i <= columns; ++i) {
        const bool interior = i > 0 && i < columns && j > 0 && j < rows;
        grid.mesh.positions.push_back(interior ? place(i + jitter(rng), j + jitter(rng)) : place(i, j));
      }
    }
    grid.mesh.uvs.assign(grid.mesh.positions.size(), glm::dvec2(0.0));
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (columns + 1) + i); };
    for (int j = 0; j < rows; ++j) {
      for (int i = 0; i < columns; ++i) {
        const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
        const bool flip = (i + j + variant) % 2 == 0;  // both diagonals occur
        const bool reverse = (i * 7 + j * 3) % 3 == 0;  // and both windings
        std::array<std::uint32_t, 3> t0 = flip ? std::array<std::uint32_t, 3>{a, b, c} : std::array<std::uint32_t, 3>{a, b, d};
        std::array<std::uint32_t, 3> t1 = flip ? std::array<std::uint32_t, 3>{a, c, d} : std::array<std::uint32_t, 3>{b, c, d};
        if (reverse) {
          std::swap(t0[1], t0[2]);
          std::swap(t1[1], t1[2]);
        }
        grid.mesh.triangles.push_back(t0);
        grid.mesh.triangles.push_back(t1);
      }
    }
    s.objects.push_back(grid);
    const std::vector<glm::dvec2> outline{exact_window(s, place(0, 0)), exact_window(s, place(columns, 0)),
                                          exact_window(s, place(columns, rows)), exact_window(s, place(0, rows))};
    INFO("variant " << variant);
    check_watertight(s, outline, 96 / (2 * 1.0));
  }
}

namespace {

using PixelSet = std::set<std::pair<int, int>>;

// The pixels the fixed pipeline's setup + row walk produce, checking on the
// way that rows come in order, once each, and spans stay in the viewport.
PixelSet fixed_pixels(const ScreenVertex (&v)[3], Cull cull, int width, int height, bool& well_formed) {
  PixelSet out;
  spanlight::TriangleSetup t{};
  if (!spanlight::setup_triangle(v, cull, height, t)) return out;
  std::int32_t last_row = -1;
  spanlight::rasterize_rows(t, width, [&](std::int32_t row, std::int32_t c0, std::int32_t c1) {
    if (row <= last_row || row < 0 || row >= height || c0 < 0 || c1 >= width || c0 > c1) well_formed = false;
    last_row = row;
    for (std::int32_t c = c0; c <= c1; ++c) out.emplace(c, row);
  });
  return out;
}

// The pixels the small-triangle setup (2_triangle/small.hpp) gives, as draw_small
// walks them; `small` false when setup_small passes the triangle to the general path.
PixelSet small_pixels(const ScreenVertex (&v)[3], Cull cull, int width, int height, bool& small, bool& well_formed) {
  PixelSet out;
  spanlight::SmallTriangle t{};
  bool covers = false;
  small = spanlight::setup_small(v, cull, height, t, covers);
  if (!small || !covers) return out;
  for (std::int32_t row = t.row_begin; row < t.row_end; ++row) {
    std::int32_t lo = -t.column0, hi = width - 1 - t.column0;
    if (t.columns(lo, hi)) {
      if (row < 0 || row >= height) well_formed = false;
      for (std::int32_t c = lo; c <= hi; ++c) out.emplace(t.column0 + c, row);
    }
    t.next_row();
  }
  return out;
}

PixelSet reference_pixels(const ScreenVertex (&v)[3], Cull cull, int width, int height) {
  const fm::SnappedVertex tri[3] = {snapped(v[0]), snapped(v[1]), snapped(v[2])};
  PixelSet out;
  // float_model's `back` culling: zero or positive area (clockwise in the image) is dropped.
  if (cull == Cull::back && fm::is_back_facing({tri[0], tri[1], tri[2]})) return out;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (fm::pixel_covered(tri, x, y)) out.emplace(x, y);
  return out;
}

}  // namespace

TEST_CASE("setup and row walk cover exactly the pixels float_model::pixel_covered accepts", "[coverage]") {
  constexpr int width = 61, height = 47;
  constexpr std::int32_t limit = (1 << 21) - 1;  // the clip stage's guard band bound (setup.hpp)
  const int cases = pt::sanitized ? 600 : 6000;
  std::mt19937_64 rng(0x5eed0002);
  auto uniform = [&](std::int64_t lo, std::int64_t hi) {
    return static_cast<std::int32_t>(std::uniform_int_distribution<std::int64_t>(lo, hi)(rng));
  };
  // One coordinate: near the viewport, on the pixel-centre / pixel-corner
  // lattice (exact ties), or anywhere within the guard band.
  auto coordinate = [&](int size) -> std::int32_t {
    switch (uniform(0, 3)) {
      case 0: return uniform(-3 * 256, (size + 3) * 256);
      case 1: return uniform(-2, size + 2) * 256 + (uniform(0, 1) ? 128 : 0);
      case 2: return uniform(-limit, limit);
      default: return uniform(-40 * 256, (size + 40) * 256);
    }
  };
  auto vertex = [&](std::int32_t x, std::int32_t y) {
    ScreenVertex v{};
    v.x = x;
    v.y = y;
    v.z = uniform(0, std::int64_t{1} << 30);
    v.inv_w_mantissa = static_cast<std::uint32_t>(uniform(std::int64_t{1} << 30, (std::int64_t{1} << 31) - 1));
    v.inv_w_exponent = uniform(30, 62);
    return v;
  };
  auto clamp_limit = [&](std::int64_t c) { return static_cast<std::int32_t>(std::clamp<std::int64_t>(c, -limit, limit)); };

  int non_empty = 0, degenerate = 0, mismatched = 0, small_cases = 0, small_mismatched = 0;
  bool well_formed = true;
  for (int n = 0; n < cases; ++n) {
    ScreenVertex v[3] = {vertex(coordinate(width), coordinate(height)), vertex(coordinate(width), coordinate(height)),
                         vertex(coordinate(width), coordinate(height))};
    const int kind = uniform(0, 9);
    if (kind == 0) {  // zero area: a repeated vertex
      const ScreenVertex& twin = v[uniform(0, 1)];
      v[2].x = twin.x;
      v[2].y = twin.y;
    } else if (kind == 1) {  // zero area: collinear, c = a + k (b - a)
      const std::int64_t k = uniform(-2, 3);
      v[2].x = clamp_limit(v[0].x + k * (std::int64_t{v[1].x} - v[0].x));
      v[2].y = clamp_limit(v[0].y + k * (std::int64_t{v[1].y} - v[0].y));
    } else if (kind == 2 || kind == 3) {  // a sliver: c a few subpixels off the line a-b
      v[2].x = clamp_limit((std::int64_t{v[0].x} + v[1].x) / 2 + uniform(-3, 3));
      v[2].y = clamp_limit((std::int64_t{v[0].y} + v[1].y) / 2 + uniform(-3, 3));
    } else if (kind == 4) {  // axis-aligned right triangle on the lattice: ties on both legs
      v[1].y = v[0].y;
      v[2].x = v[0].x;
    }
    const bool zero_area = spanlight::signed_double_area(v[0], v[1], v[2]) == 0;
    degenerate += zero_area;
    for (const Cull cull : {Cull::none, Cull::back}) {
      bool ok = true;
      const PixelSet got = fixed_pixels(v, cull, width, height, ok);
      const PixelSet want = reference_pixels(v, cull, width, height);
      well_formed &= ok;
      non_empty += !want.empty();
      if (got != want) {
        ++mismatched;
        if (mismatched <= 5) {
          UNSCOPED_INFO("mismatch: (" << v[0].x << "," << v[0].y << ") (" << v[1].x << "," << v[1].y << ") ("
                                      << v[2].x << "," << v[2].y << ") cull " << static_cast<int>(cull) << ": fixed "
                                      << got.size() << " pixels, reference " << want.size());
        }
      }
      if (zero_area) CHECK(got.empty());
      bool small = false;
      const PixelSet got_small = small_pixels(v, cull, width, height, small, ok);
      well_formed &= ok;
      if (small) {
        ++small_cases;
        small_mismatched += got_small != want;
      }
    }
  }
  INFO(cases << " triangles, " << degenerate << " of zero area, " << non_empty << " non-empty (triangle, cull) cases, "
             << small_cases << " taken by the small-triangle setup");
  CHECK(small_cases > cases / 10);
  CHECK(small_mismatched == 0);
  CHECK(non_empty > cases / 4);  // enough of them actually touch the viewport
  CHECK(degenerate > cases / 20);
  CHECK(well_formed);
  CHECK(mismatched == 0);
}

// A small triangle's edges step down the rows in one of two ways (2_triangle/small.hpp: with
// the core's divide, or by search where it has none, Cortex-M0+); the host draws with the first,
// so here the second is held to it: the same quotient and remainder on every row of the box,
// for edges of every slope, from every row.
TEST_CASE("a small triangle's edge gives the same bounds stepped by division and by search", "[coverage][small]") {
  const int cases = pt::sanitized ? 20000 : 200000;
  std::mt19937_64 rng(0x5eed0007);
  constexpr std::int32_t box = spanlight::small_triangle_extent + 256;  // vertices relative to the corner
  auto coordinate = [&](std::int32_t range) {
    // Every scale of edge: from a subpixel to the whole box.
    const int bits = static_cast<int>(rng() % 15) + 1;
    return static_cast<std::int32_t>(rng() % static_cast<std::uint64_t>(std::min(range, std::int32_t{1} << bits)));
  };
  long rows = 0;
  for (int i = 0; i < cases; ++i) {
    const std::int32_t ax = coordinate(box), ay = coordinate(box), bx = coordinate(box), by = coordinate(box);
    if (ay == by) continue;  // horizontal: a small triangle bounds no row with it
    spanlight::SmallEdge e;
    e.start(ax, ay, bx, by);
    // The rows the edge spans (centres within its ends; y >= 0 here, so none above row 0).
    const auto [first, last] = spanlight::rows_centred_in(std::min(ay, by), std::max(ay, by));
    if (first >= last) continue;
    const std::int32_t start = first + static_cast<std::int32_t>(rng() % static_cast<std::uint64_t>(last - first));
    auto divided = e.bound<false>(start);
    auto searched = e.bound<true>(start);
    for (std::int32_t row = start; row < last; ++row, ++rows) {
      INFO("edge (" << ax << ", " << ay << ") - (" << bx << ", " << by << "), row " << row);
      REQUIRE(searched.quotient == divided.quotient);
      REQUIRE(searched.remainder == divided.remainder);
      divided.next_row();
      searched.next_row();
    }
  }
  INFO(rows << " rows");
  CHECK(rows > cases);
}
