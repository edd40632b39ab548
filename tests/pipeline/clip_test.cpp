// The clip stage cuts its polygon in place (1_vertex/clip.hpp). Here it is held
// to the two-buffer Sutherland-Hodgman it replaces, field for field, on random
// polygons: triangles cut by all six planes (the convex case, at most one exit
// a plane), and bent polygons whose vertices cross one plane several times
// (what rounding can make of cut vertices lying along a plane), where the
// input has to move up before the cut. A polygon the cut would take past the
// array's nine vertices is refused instead of written beyond them.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <vector>

#include "spanlight/1_vertex/clip.hpp"

namespace {

using spanlight::ClipPlane;
using Vertex = spanlight::ClipVertex<1>;

// The two-buffer cut: what edge i gives, appended to a fresh list.
std::vector<Vertex> cut_two_buffers(const std::vector<Vertex>& in, ClipPlane plane, std::int64_t guard) {
  std::vector<Vertex> out;
  const auto n = in.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex& a = in[i];
    const Vertex& b = in[(i + 1) % n];
    const std::int64_t da = spanlight::plane_distance(plane, a.clip, guard);
    const std::int64_t db = spanlight::plane_distance(plane, b.clip, guard);
    if (da >= 0) out.push_back(a);
    Vertex cut{};
    if (da >= 0 && db < 0) {
      spanlight::lerp_vertex(a, b, spanlight::crossing(da, db), 0, 1, cut);
      out.push_back(cut);
    }
    if (da < 0 && db >= 0) {
      spanlight::lerp_vertex(b, a, spanlight::crossing(db, da), 0, 1, cut);
      out.push_back(cut);
    }
  }
  return out;
}

bool same(const Vertex& a, const Vertex& b) {
  auto eq = [](const fixedpoint::Vec4Wide& p, const fixedpoint::Vec4Wide& q) {
    return p.x == q.x && p.y == q.y && p.z == q.z && p.w == q.w;
  };
  return eq(a.clip, b.clip) && a.u == b.u && a.v == b.v && eq(a.proj[0], b.proj[0]);
}

// Components within the transform's bound (|c| < 2^40 here: far inside it).
Vertex random_vertex(std::mt19937_64& rng, std::int64_t scale) {
  std::uniform_int_distribution<std::int64_t> c(-scale, scale);
  std::uniform_int_distribution<std::int32_t> uv(-(1 << 28), 1 << 28);
  Vertex v{};
  v.clip = {c(rng), c(rng), c(rng), c(rng)};
  v.u = uv(rng);
  v.v = uv(rng);
  v.proj[0] = {c(rng), c(rng), c(rng), c(rng)};
  return v;
}

constexpr ClipPlane planes[] = {ClipPlane::near, ClipPlane::far, ClipPlane::left,
                                ClipPlane::right, ClipPlane::bottom, ClipPlane::top};

}  // namespace

TEST_CASE("a triangle clipped in place by the six planes is the two-buffer polygon, vertex for vertex", "[clip]") {
  std::mt19937_64 rng(20261207);
  const std::int64_t guard = 6;  // draw.hpp's guard_band for a 320 x 240 view
  int clipped = 0, dropped = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::vector<Vertex> reference;
    spanlight::ClipPolygon<1> poly{};
    poly.count = 3;
    for (int k = 0; k < 3; ++k) {
      poly.v[k] = random_vertex(rng, std::int64_t{1} << 40);
      // w mostly positive, so that many triangles keep something.
      poly.v[k].clip.w = (poly.v[k].clip.w < 0 ? -poly.v[k].clip.w : poly.v[k].clip.w) - (std::int64_t{1} << 37);
      reference.push_back(poly.v[k]);
    }
    bool reference_kept = true;
    for (ClipPlane plane : planes) {
      reference = cut_two_buffers(reference, plane, guard);
      if (reference.size() < 3) {
        reference_kept = false;
        break;
      }
    }
    const bool kept = spanlight::clip_polygon(poly, guard, 0, 1);
    REQUIRE(kept == reference_kept);
    if (!kept) {
      ++dropped;
      continue;
    }
    REQUIRE(reference.size() <= spanlight::max_clipped_vertices);
    REQUIRE(poly.count == static_cast<int>(reference.size()));
    for (int k = 0; k < poly.count; ++k) REQUIRE(same(poly.v[k], reference[static_cast<std::size_t>(k)]));
    clipped += poly.count > 3;
  }
  // Both outcomes occur often (the test would prove nothing otherwise).
  CHECK(clipped > 1000);
  CHECK(dropped > 1000);
}

TEST_CASE("a bent polygon that leaves a plane several times is cut in place as the two-buffer cut, or refused",
          "[clip]") {
  std::mt19937_64 rng(7);
  const std::int64_t guard = 6;  // draw.hpp's guard_band for a 320 x 240 view
  std::uniform_int_distribution<int> size(3, spanlight::max_clipped_vertices);
  int multiple_exits = 0, refused = 0;
  for (int trial = 0; trial < 50000; ++trial) {
    const int n = size(rng);
    spanlight::ClipPolygon<1> poly{};
    poly.count = n;
    std::vector<Vertex> input;
    for (int k = 0; k < n; ++k) {
      poly.v[k] = random_vertex(rng, std::int64_t{1} << 40);  // signs at random: any number of exits
      input.push_back(poly.v[k]);
    }
    const ClipPlane plane = planes[trial % 6];
    int exits = 0;
    for (int k = 0; k < n; ++k) {
      const bool in = spanlight::plane_distance(plane, input[static_cast<std::size_t>(k)].clip, guard) >= 0;
      const bool next_in = spanlight::plane_distance(plane, input[static_cast<std::size_t>((k + 1) % n)].clip, guard) >= 0;
      exits += in && !next_in;
    }
    const std::vector<Vertex> reference = cut_two_buffers(input, plane, guard);
    const bool fits = reference.size() <= spanlight::max_clipped_vertices && n + (exits > 1 ? exits - 1 : 0) <= spanlight::max_clipped_vertices;
    const bool kept = spanlight::clip_against(poly, plane, guard, 0, 1);
    if (fits && reference.size() >= 3) {
      REQUIRE(kept);
      multiple_exits += exits > 1;
      REQUIRE(poly.count == static_cast<int>(reference.size()));
      for (int k = 0; k < poly.count; ++k) REQUIRE(same(poly.v[k], reference[static_cast<std::size_t>(k)]));
    } else {
      REQUIRE(!kept);
      refused += reference.size() >= 3;
    }
  }
  CHECK(multiple_exits > 1000);
  CHECK(refused > 100);
}
