// The coverage rule: snapped vertices, integer edge functions, top-left ties.
// The strong properties: any partition of an area into triangles covers each
// pixel centre inside it exactly once, and two different partitions of the same
// polygon cover exactly the same pixels.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include "float_model/float_model.hpp"

namespace fm = spanlight::float_model;
using fm::SnappedVertex;

namespace {

constexpr std::int64_t px = fm::subpixels_per_pixel;  // one pixel in subpixels

// The centre of pixel (x, y), in subpixels.
SnappedVertex centre(int x, int y) { return fm::pixel_centre(x, y); }

struct Tri {
  SnappedVertex v[3];
};

// How many of the triangles cover each pixel of a width x height grid.
std::vector<int> coverage_counts(const std::vector<Tri>& triangles, int width, int height) {
  std::vector<int> counts(static_cast<std::size_t>(width * height), 0);
  for (const Tri& t : triangles) {
    for (const auto& [x, y] : fm::covered_pixels(t.v, width, height)) ++counts[static_cast<std::size_t>(y * width + x)];
  }
  return counts;
}

// Fan of `slices` triangles around `centre_point`, alternately listed clockwise
// and counter-clockwise (coverage must not depend on the winding).
std::vector<Tri> closed_fan(SnappedVertex middle, double radius_px, int slices, double phase) {
  std::vector<SnappedVertex> rim;
  for (int k = 0; k < slices; ++k) {
    const double angle = phase + 2.0 * std::numbers::pi * k / slices;
    rim.push_back({middle.x + std::llround(radius_px * px * std::cos(angle)),
                   middle.y + std::llround(radius_px * px * std::sin(angle))});
  }
  std::vector<Tri> fan;
  for (int k = 0; k < slices; ++k) {
    const SnappedVertex a = rim[static_cast<std::size_t>(k)];
    const SnappedVertex b = rim[static_cast<std::size_t>((k + 1) % slices)];
    fan.push_back(k % 2 == 0 ? Tri{{middle, a, b}} : Tri{{middle, b, a}});
  }
  return fan;
}

// The same polygon triangulated from its first rim vertex instead of the middle.
std::vector<Tri> rim_fan(const std::vector<Tri>& fan) {
  std::vector<SnappedVertex> rim;
  for (std::size_t k = 0; k < fan.size(); ++k) rim.push_back(k % 2 == 0 ? fan[k].v[1] : fan[k].v[2]);
  std::vector<Tri> out;
  for (std::size_t k = 1; k + 1 < rim.size(); ++k) out.push_back({{rim[0], rim[k], rim[k + 1]}});
  return out;
}

}  // namespace

TEST_CASE("a closed 64-slice fan covers every pixel of its polygon exactly once", "[coverage]") {
  constexpr int size = 72;
  // Centres on a pixel centre (every slice's apex ties there), on a pixel corner,
  // and at odd subpixel positions.
  const std::vector<SnappedVertex> middles{centre(36, 36), {36 * px, 36 * px}, {36 * px + 37, 35 * px + 201},
                                           {35 * px + 128, 36 * px + 5}};
  for (const SnappedVertex middle : middles) {
    for (const double phase : {0.0, 0.013, std::numbers::pi / 64.0}) {
      const std::vector<Tri> fan = closed_fan(middle, 30.0, 64, phase);
      const std::vector<int> counts = coverage_counts(fan, size, size);
      const std::vector<int> reference = coverage_counts(rim_fan(fan), size, size);
      int covered = 0;
      for (std::size_t i = 0; i < counts.size(); ++i) {
        INFO("pixel " << i % size << ", " << i / size << " middle " << middle.x << ", " << middle.y);
        REQUIRE(counts[i] <= 1);
        REQUIRE(counts[i] == reference[i]);  // same polygon, other triangulation: same pixels
        covered += counts[i];
      }
      // The apex pixel when the apex is a pixel centre: 64 triangles meet, one wins.
      if (middle == centre(36, 36)) REQUIRE(counts[36 * size + 36] == 1);
      // A radius-30 circle holds about pi * 900 pixels.
      REQUIRE(std::abs(covered - 2827) < 40);
    }
  }
}

TEST_CASE("a tiled grid of triangles hits every pixel of its rectangle exactly once", "[coverage]") {
  constexpr int size = 64;
  constexpr int cells = 8;                   // 8 x 8 quads, 16 triangles per row
  constexpr std::int64_t cell = 6 * px;      // 6 pixels a side
  constexpr std::int64_t origin = 5 * px + 128;  // on pixel centres: the outer edges run through centres
  std::mt19937 random(12345);
  // Interior vertices move by whole pixels, half pixels (onto centres) or odd subpixels.
  const std::int64_t jitters[] = {0, 128, -128, 256, -256, 37, -91, 200};
  std::uniform_int_distribution<std::size_t> pick(0, std::size(jitters) - 1);

  std::vector<std::vector<SnappedVertex>> grid(cells + 1, std::vector<SnappedVertex>(cells + 1));
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      SnappedVertex v{origin + i * cell, origin + j * cell};
      if (i > 0 && i < cells && j > 0 && j < cells) {
        v.x += jitters[pick(random)];
        v.y += jitters[pick(random)];
      }
      grid[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)] = v;
    }
  }
  std::vector<Tri> tiles;
  for (std::size_t j = 0; j < cells; ++j) {
    for (std::size_t i = 0; i < cells; ++i) {
      const SnappedVertex a = grid[j][i], b = grid[j][i + 1], c = grid[j + 1][i + 1], d = grid[j + 1][i];
      if ((i + j) % 2 == 0) {  // alternate the diagonal
        tiles.push_back({{a, b, c}});
        tiles.push_back({{a, c, d}});
      } else {
        tiles.push_back({{a, b, d}});
        tiles.push_back({{d, b, c}});
      }
    }
  }
  const SnappedVertex tl = grid[0][0], tr = grid[0][cells], br = grid[cells][cells], bl = grid[cells][0];
  const std::vector<int> counts = coverage_counts(tiles, size, size);
  const std::vector<int> rectangle = coverage_counts({{{tl, tr, br}}, {{tl, br, bl}}}, size, size);
  int inside = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      INFO("pixel " << x << ", " << y);
      const std::size_t i = static_cast<std::size_t>(y * size + x);
      REQUIRE(counts[i] == rectangle[i]);
      // The rectangle spans centres 5..53: top and left rows are in, bottom and right out.
      const bool expected = x >= 5 && x < 53 && y >= 5 && y < 53;
      REQUIRE(rectangle[i] == (expected ? 1 : 0));
      inside += counts[i];
    }
  }
  REQUIRE(inside == 48 * 48);
}

TEST_CASE("ties follow the Direct3D top-left rule as seen in the output image", "[coverage]") {
  // Square with corners on the centres of pixels (1,1) and (5,5), cut along the
  // diagonal from its top-right to its bottom-left corner.
  const SnappedVertex a = centre(1, 1), b = centre(5, 1), c = centre(5, 5), d = centre(1, 5);
  const SnappedVertex upper_left[3] = {a, b, d};
  const SnappedVertex lower_right[3] = {b, c, d};

  SECTION("top edge in, left edge in, their shared vertex in") {
    CHECK(fm::pixel_covered(upper_left, 3, 1));  // on the top edge
    CHECK(fm::pixel_covered(upper_left, 1, 3));  // on the left edge
    CHECK(fm::pixel_covered(upper_left, 1, 1));  // top-left corner
    CHECK(fm::pixel_covered(upper_left, 2, 2));  // strictly inside
  }
  SECTION("the diagonal is a right edge of the upper-left half and a left edge of the lower-right half") {
    for (int k = 2; k <= 4; ++k) {  // (2,4), (3,3), (4,2) lie on the diagonal
      CHECK_FALSE(fm::pixel_covered(upper_left, k, 6 - k));
      CHECK(fm::pixel_covered(lower_right, k, 6 - k));
    }
  }
  SECTION("bottom and right edges are out") {
    CHECK_FALSE(fm::pixel_covered(lower_right, 3, 5));  // bottom edge
    CHECK_FALSE(fm::pixel_covered(lower_right, 5, 3));  // right edge
    CHECK_FALSE(fm::pixel_covered(lower_right, 5, 5));  // bottom-right corner
    CHECK_FALSE(fm::pixel_covered(upper_left, 5, 1));   // top-right corner: top edge meets the diagonal
    CHECK_FALSE(fm::pixel_covered(upper_left, 1, 5));   // bottom-left corner
  }
  SECTION("a horizontal edge shared by two triangles belongs to the one below it") {
    const SnappedVertex left = centre(0, 3), right = centre(6, 3);
    const SnappedVertex above[3] = {left, right, centre(3, 0)};
    const SnappedVertex below[3] = {left, centre(3, 6), right};
    for (int x = 1; x <= 5; ++x) {
      CHECK_FALSE(fm::pixel_covered(above, x, 3));
      CHECK(fm::pixel_covered(below, x, 3));
    }
  }
  SECTION("a vertical edge shared by two triangles belongs to the one on its right") {
    const SnappedVertex top = centre(3, 0), bottom = centre(3, 6);
    const SnappedVertex left_tri[3] = {top, bottom, centre(0, 3)};
    const SnappedVertex right_tri[3] = {top, centre(6, 3), bottom};
    for (int y = 1; y <= 5; ++y) {
      CHECK_FALSE(fm::pixel_covered(left_tri, 3, y));
      CHECK(fm::pixel_covered(right_tri, 3, y));
    }
  }
  SECTION("the winding does not change coverage") {
    const SnappedVertex reversed[3] = {a, d, b};
    for (int y = 0; y < 7; ++y) {
      for (int x = 0; x < 7; ++x) CHECK(fm::pixel_covered(upper_left, x, y) == fm::pixel_covered(reversed, x, y));
    }
  }
}

TEST_CASE("edge classification follows the brief's formulas", "[coverage]") {
  // Interior has E > 0 in a y-down frame: left edges go up (dy < 0), top edges go right.
  CHECK(fm::is_top_left({0, 100}, {0, 0}));        // going up: interior to its right
  CHECK_FALSE(fm::is_top_left({0, 0}, {0, 100}));  // going down: a right edge
  CHECK(fm::is_top_left({0, 0}, {100, 0}));        // horizontal going right: interior below, top
  CHECK_FALSE(fm::is_top_left({100, 0}, {0, 0}));  // horizontal going left: a bottom edge
  CHECK(fm::is_top_left({50, 100}, {0, 0}));       // up and to the left: still left
  // Edge values: inside positive for a triangle of positive area.
  const SnappedVertex a{0, 0}, b{256, 0}, c{0, 256};
  CHECK(fm::twice_signed_area(a, b, c) == 256 * 256);
  CHECK(fm::edge_function(a, b, {10, 10}) > 0);
}

TEST_CASE("a zero-area triangle covers nothing", "[coverage]") {
  const SnappedVertex line[3] = {centre(0, 0), centre(4, 4), centre(8, 8)};
  const SnappedVertex point[3] = {centre(2, 2), centre(2, 2), centre(2, 2)};
  CHECK(fm::covered_pixels(line, 10, 10).empty());
  CHECK(fm::covered_pixels(point, 10, 10).empty());
  CHECK_FALSE(fm::pixel_covered(point, 2, 2));
}

TEST_CASE("coverage stops at the viewport and survives vertices far outside it", "[coverage]") {
  // One huge triangle, the kind a near-clipped ground plane produces (millions of pixels off screen).
  const std::int64_t far = std::int64_t{1} << 50;
  const SnappedVertex huge[3] = {{-far, -far}, {2 * far, -far}, {-far, 2 * far}};  // holds the viewport
  const auto pixels = fm::covered_pixels(huge, 32, 24);
  CHECK(pixels.size() == 32 * 24);
}

TEST_CASE("back-facing means clockwise as seen in the output image", "[coverage]") {
  // y down: top-left, top-right, bottom-left runs clockwise on the screen.
  const std::array<SnappedVertex, 3> clockwise{SnappedVertex{0, 0}, SnappedVertex{256, 0}, SnappedVertex{0, 256}};
  const std::array<SnappedVertex, 3> counter_clockwise{clockwise[0], clockwise[2], clockwise[1]};
  CHECK(fm::is_back_facing(clockwise));
  CHECK_FALSE(fm::is_back_facing(counter_clockwise));
}

TEST_CASE("snapping rounds to the nearest 1/256 pixel, halves away from zero", "[coverage]") {
  CHECK(fm::snap({1.0, 2.0, 0.5}) == SnappedVertex{256, 512});
  CHECK(fm::snap({0.5 / 256.0, -0.5 / 256.0, 0.5}) == SnappedVertex{1, -1});
  CHECK(fm::snap({0.49 / 256.0, 10.0 + 0.51 / 256.0, 0.5}) == SnappedVertex{0, 2561});
  CHECK_THROWS_AS(fm::snap({1e300, 0.0, 0.5}), std::range_error);
}
