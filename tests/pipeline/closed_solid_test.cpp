// Closed solids (host_tools/prepare/closed_mesh.hpp, 1_vertex/closed.hpp): prepare
// marks a mesh that is closed, consistently wound and outward; draw_pass then culls
// its back faces when it lies wholly in front of the near plane in a view that does
// not mirror it, and the picture is the one both sides give. In a mirror, cut open
// by the near plane, or around the eye, it draws both sides.
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "pipeline_support.hpp"
#include "prepare/closed_mesh.hpp"
#include "sphere_scene.hpp"
#include "spanlight/1_vertex/closed.hpp"
#include "spanlight/scene_features.hpp"

using namespace spanlight;
using namespace spanlight::ptest;

namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// A cube of side 2 s at (cx, 0, 0), counter-clockwise seen from outside.
void add_cube(std::vector<std::int32_t>& xyz, Triangles& triangles, std::int32_t cx, std::int32_t s) {
  const auto base = static_cast<std::uint32_t>(xyz.size() / 3);
  for (int k = 0; k < 8; ++k) {  // corner k: x, y, z from bits 0, 1, 2
    xyz.push_back(cx + ((k & 1) ? s : -s));
    xyz.push_back((k & 2) ? s : -s);
    xyz.push_back((k & 4) ? s : -s);
  }
  // Each face's corners counter-clockwise seen from outside, as two triangles.
  const std::uint32_t faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) {
    triangles.push_back({base + f[0], base + f[1], base + f[2]});
    triangles.push_back({base + f[0], base + f[2], base + f[3]});
  }
}

Triangles reversed(Triangles t) {
  for (auto& tri : t) std::swap(tri[1], tri[2]);
  return t;
}

// Six times the exact determinant of to_clip's rows x, y, w over x, y, z.
__extension__ typedef __int128 Wide;
Wide exact_determinant(const Mat4Block& m) {
  auto at = [&](int row, int col) { return Wide{m.m[col * 4 + row]}; };
  const int r[3] = {0, 1, 3};
  return at(r[0], 0) * (at(r[1], 1) * at(r[2], 2) - at(r[1], 2) * at(r[2], 1)) -
         at(r[0], 1) * (at(r[1], 0) * at(r[2], 2) - at(r[1], 2) * at(r[2], 0)) +
         at(r[0], 2) * (at(r[1], 0) * at(r[2], 1) - at(r[1], 1) * at(r[2], 0));
}

struct RowCounter : NoHooks {
  int* triangles_with_rows;
  void triangle_rows() { ++*triangles_with_rows; }
};

struct Drawn {
  ObservedFrame frame;
  int triangles_with_rows = 0;
};

Drawn draw(const prepare::PreparedStorage& prepared, std::uint8_t depth_bits) {
  Drawn d;
  RowCounter counter{};
  counter.triangles_with_rows = &d.triangles_with_rows;
  const Knobs knobs = knobs_with(Passes::fused, depth_bits, PixelFormat::rgb565);
  prepare::render_fixed_with_hooks(prepared, knobs, counter);
  d.frame = render_observed(prepared, knobs);
  return d;
}

bool same_picture(const ObservedFrame& a, const ObservedFrame& b) { return a.depth == b.depth && a.rgb == b.rgb; }

// The sphere scene with the camera moved and the sphere's model matrix set.
scene::Scene sphere_seen_from(glm::dvec3 eye, double near, glm::dmat4 model, scene::Cull cull) {
  scene::Scene s = sphere_scene(cull);
  s.camera.eye = eye;
  s.camera.near = near;
  s.objects[0].model = model;
  return s;
}

}  // namespace

TEST_CASE("closed_solid: closed, consistently wound and outward, by position", "[pipeline][closed]") {
  std::vector<std::int32_t> xyz;
  Triangles cube;
  add_cube(xyz, cube, 0, 1 << 16);
  CHECK(prepare::closed_solid(xyz, cube));
  CHECK_FALSE(prepare::closed_solid(xyz, reversed(cube)));  // inward: negative volume
  CHECK_FALSE(prepare::closed_solid(xyz, Triangles(cube.begin() + 1, cube.end())));  // a hole
  Triangles doubled = cube;
  doubled.push_back(cube[0]);  // an edge a -> b twice
  CHECK_FALSE(prepare::closed_solid(xyz, doubled));
  CHECK_FALSE(prepare::closed_solid(xyz, {}));

  Triangles with_degenerate = cube;
  with_degenerate.push_back({0, 0, 7});  // two corners at one position: no part
  CHECK(prepare::closed_solid(xyz, with_degenerate));

  // A seam: face 0's corners repeated as vertices of their own (same positions, other indices).
  std::vector<std::int32_t> seamed = xyz;
  Triangles seam_cube = cube;
  for (int k : {0, 1}) {
    for (std::uint32_t& index : seam_cube[static_cast<std::size_t>(k)]) {
      const auto copy = static_cast<std::uint32_t>(seamed.size() / 3);
      for (int c = 0; c < 3; ++c) seamed.push_back(xyz[index * 3 + static_cast<std::uint32_t>(c)]);
      index = copy;
    }
  }
  CHECK(prepare::closed_solid(seamed, seam_cube));

  // Two parts, overlapping: each must enclose a positive volume.
  std::vector<std::int32_t> two = xyz;
  Triangles both = cube, second;
  add_cube(two, second, 1 << 15, 1 << 16);
  both.insert(both.end(), second.begin(), second.end());
  CHECK(prepare::closed_solid(two, both));
  Triangles one_inward = cube;
  for (const auto& t : reversed(second)) one_inward.push_back(t);
  CHECK_FALSE(prepare::closed_solid(two, one_inward));  // the total volume is 0, not below it
}

TEST_CASE("prepare marks the closed models closed and the open ones open, and bake links the culling for them", "[pipeline][closed]") {
  CHECK(prepare::prepare_scene(sphere_scene(scene::Cull::none))->objects[0].closed);
  const auto bear = prepare::prepare_scene(scene::load_scene(scene_file("mesh_bear")));
  for (const ObjectData& object : bear->objects) CHECK(object.closed);  // the bear and its buttons
  const auto terrain = prepare::prepare_scene(scene::load_scene(scene_file("checks/mesh_terrain")));
  CHECK_FALSE(terrain->objects[0].closed);  // a patch of ground
  // Only a scene with one compiles the culling of closed solids (Features::closed_solids).
  CHECK(features_of(bear->scene, Knobs{}).closed_solids);
  CHECK_FALSE(features_of(terrain->scene, Knobs{}).closed_solids);
  const auto culled = prepare::prepare_scene(sphere_scene(scene::Cull::back));
  CHECK_FALSE(features_of(culled->scene, Knobs{}).closed_solids);  // culled already
}

TEST_CASE("view_keeps_winding: true only where the exact determinant is negative", "[pipeline][closed]") {
  std::mt19937 rng(19);
  std::uniform_int_distribution<std::int32_t> any(INT32_MIN, INT32_MAX);
  std::uniform_int_distribution<int> bits(0, 31);
  const int cases = sanitized ? 20000 : 200000;
  int kept = 0;
  for (int n = 0; n < cases; ++n) {
    Mat4Block m{};
    for (std::int32_t& x : m.m) x = any(rng) >> bits(rng);  // rows of any scale
    if (n % 4 == 0) {  // nearly flat: row w close to a multiple of row x
      for (int col = 0; col < 3; ++col) m.m[col * 4 + 3] = m.m[col * 4 + 0] / 2 + (any(rng) >> 28);
    }
    const Wide det = exact_determinant(m);
    const bool keeps = view_keeps_winding(m);
    kept += keeps;
    if (keeps) REQUIRE(det < 0);
    // Clearly negative (beyond 2^-4 of the rows' largest entries' product, each row above 2^14):
    // the reduced determinant is below -2^35, so it must say so.
    Wide scale = 1;
    bool all_shifted = true;
    for (int row : {0, 1, 3}) {
      std::int64_t largest = 0;
      for (int col = 0; col < 3; ++col) largest = std::max(largest, std::abs(std::int64_t{m.m[col * 4 + row]}));
      all_shifted = all_shifted && largest >= (1 << 14);
      scale *= largest;
    }
    if (all_shifted && det < -(scale / 16)) REQUIRE(keeps);
  }
  CHECK(kept > cases / 8);  // the property is not vacuous
}

TEST_CASE("view_keeps_winding: a camera keeps it, a mirror or an orthographic view does not", "[pipeline][closed]") {
  const scene::Scene s = sphere_scene(scene::Cull::none);
  const glm::dmat4 view_projection = scene::camera_view_projection(s);
  CHECK(view_keeps_winding(prepare::to_mat4_block(view_projection)));
  CHECK_FALSE(view_keeps_winding(prepare::to_mat4_block(view_projection * glm::scale(glm::dmat4(1.0), {-1.0, 1.0, 1.0}))));
  CHECK_FALSE(view_keeps_winding(prepare::to_mat4_block(glm::ortho(-1.0, 1.0, -1.0, 1.0, 0.5, 10.0))));
  // Flattened a million times: its sign is not known from the reduced rows, so both sides.
  CHECK_FALSE(view_keeps_winding(prepare::to_mat4_block(view_projection * glm::scale(glm::dmat4(1.0), {1.0, 1.0, 1e-6}))));
}

TEST_CASE("a closed solid seen from outside draws as with its back faces culled", "[pipeline][closed]") {
  const auto closed = prepare::prepare_scene(sphere_scene(scene::Cull::none));
  const auto culled = prepare::prepare_scene(sphere_scene(scene::Cull::back));
  const auto open = prepare::prepare_scene(sphere_scene(scene::Cull::none));
  open->objects[0].closed = false;
  REQUIRE(closed->objects[0].closed);
  for (const std::uint8_t depth_bits : {std::uint8_t{24}, std::uint8_t{16}}) {
    INFO("depth bits " << int{depth_bits});
    const Drawn c = draw(*closed, depth_bits), b = draw(*culled, depth_bits), o = draw(*open, depth_bits);
    CHECK(same_picture(c.frame, b.frame));
    CHECK(same_picture(c.frame, o.frame));  // both sides give the same picture here
    CHECK(c.triangles_with_rows == b.triangles_with_rows);
    CHECK(c.triangles_with_rows < o.triangles_with_rows);
  }
}

TEST_CASE("a closed solid in a mirror, cut by the near plane or around the eye draws both sides", "[pipeline][closed]") {
  struct View {
    const char* name;
    glm::dvec3 eye;
    double near;
    glm::dmat4 model;
  };
  const glm::dmat4 mirror = glm::scale(glm::dmat4(1.0), {-1.0, 1.0, 1.0});
  const View views[] = {{"mirrored", {0.3, 0.5, 3.5}, 0.5, mirror},
                        {"cut by the near plane", {0.3, 0.5, 1.4}, 0.6, glm::dmat4(1.0)},
                        {"around the eye", {0.2, 0.1, 0.3}, 0.05, glm::dmat4(1.0)}};
  for (const View& v : views) {
    INFO(v.name);
    const auto closed = prepare::prepare_scene(sphere_seen_from(v.eye, v.near, v.model, scene::Cull::none));
    const auto open = prepare::prepare_scene(sphere_seen_from(v.eye, v.near, v.model, scene::Cull::none));
    const auto culled = prepare::prepare_scene(sphere_seen_from(v.eye, v.near, v.model, scene::Cull::back));
    REQUIRE(closed->objects[0].closed);
    open->objects[0].closed = false;
    const Drawn c = draw(*closed, 24), o = draw(*open, 24), b = draw(*culled, 24);
    CHECK(same_picture(c.frame, o.frame));
    CHECK(c.triangles_with_rows == o.triangles_with_rows);
    CHECK_FALSE(same_picture(c.frame, b.frame));  // here culling would lose faces that show
  }
}

TEST_CASE("faces_away is setup's cull test: a back face leaves the loop only where setup would cull it", "[pipeline][closed]") {
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::int32_t> window(-(1 << 21) + 1, (1 << 21) - 1), near(-(1 << 15), (1 << 15) - 1);
  const int cases = sanitized ? 20000 : 200000;
  int away = 0;
  for (int n = 0; n < cases; ++n) {
    ScreenVertex v[3]{};
    v[0].x = window(rng);
    v[0].y = window(rng);
    for (int k = 1; k < 3; ++k) {  // half of them small, as a model's triangles: the 15-bit products
      v[k].x = n % 2 ? v[0].x + near(rng) / (1 << (n % 13)) : window(rng);
      v[k].y = n % 2 ? v[0].y + near(rng) / (1 << (n % 11)) : window(rng);
    }
    if (n % 7 == 0) {  // collinear: no area (it may leave the window range; only the sign is read)
      v[2].x = v[0].x + 2 * (v[1].x - v[0].x);
      v[2].y = v[0].y + 2 * (v[1].y - v[0].y);
    }
    const bool faces = faces_away(v[0], v[1], v[2]);
    REQUIRE(faces == (signed_double_area(v[0], v[1], v[2]) > 0));
    TriangleSetup setup{};
    if (faces) REQUIRE_FALSE(setup_triangle(v, Cull::back, 240, setup));
    away += faces;
  }
  CHECK(away > cases / 4);
}

