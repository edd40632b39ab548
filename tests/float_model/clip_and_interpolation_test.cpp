// Clipping, depth, perspective-correct attributes and culling, checked against
// values worked out from the geometry: the eye ray through a pixel centre meets
// the surface at a point whose uv and projector coordinates are known exactly.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>
#include <map>
#include <utility>

#include "float_model/clip.hpp"
#include "float_model/float_model.hpp"
#include "float_model/raster.hpp"
#include "float_model/transform.hpp"
#include "test_scenes.hpp"

namespace fm = spanlight::float_model;
namespace scene = spanlight::scene;
using spanlight::test::quad;

namespace {

// 64 x 64, eye at the origin looking down -z, 90 degrees: x/w = x_eye / d at depth d.
scene::Scene floor_scene() {
  return spanlight::test::empty_scene(64, 64, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90.0, 0.5, 10.0);
}

// The floor y = -1, with uv an affine function of the world position over the
// whole quad: u = (x + 4) / 8, v = (-z - 1) / 3.
glm::dvec2 floor_uv(glm::dvec3 p) { return {(p.x + 4.0) / 8.0, (-p.z - 1.0) / 3.0}; }

scene::Object floor_quad(double near_z, double far_z, double near_half_width) {
  const glm::dvec3 a(-near_half_width, -1, near_z), b(near_half_width, -1, near_z), c(4, -1, far_z), d(-4, -1, far_z);
  return quad("floor", {a, b, c, d}, {floor_uv(a), floor_uv(b), floor_uv(c), floor_uv(d)});
}

// Where the eye ray through the centre of pixel (px, py) meets the plane y = -1.
glm::dvec3 floor_point(const scene::Scene& s, int px, int py) {
  const double focal = 1.0 / std::tan(glm::radians(s.camera.fovy_deg) / 2.0);  // glm::perspective's [1][1]
  const double x_ndc = (px + 0.5) / s.width * 2.0 - 1.0;
  const double y_ndc = 1.0 - (py + 0.5) / s.height * 2.0;
  const double depth = -focal / y_ndc;  // y_eye = y_ndc * depth / focal = -1
  return {x_ndc * depth / focal, -1.0, -depth};
}

struct Sample {
  int hits = 0;
  double depth = 0.0;
  glm::dvec2 uv{0.0};
  glm::dvec4 strq{0.0};
};

// Draws every triangle of the scene's objects and records what each pixel got.
std::map<std::pair<int, int>, Sample> rasterize_all(const scene::Scene& s) {
  std::map<std::pair<int, int>, Sample> samples;
  for (const scene::Object& object : s.objects) {
    const fm::ObjectTransform transform = fm::eye_transform(s, object);
    for (std::size_t i = 0; i < object.mesh.triangles.size(); ++i) {
      fm::draw_triangle(fm::transform_triangle(transform, object.mesh, i), {s.width, s.height}, object.cull,
                        [&](const fm::ClipTriangle& triangle, const fm::Fragment& fragment) {
                          Sample& sample = samples[{fragment.x, fragment.y}];
                          ++sample.hits;
                          sample.depth = fragment.depth;
                          sample.uv = fm::interpolate_uv(triangle, fragment);
                          if (!s.projectors.empty()) sample.strq = fm::interpolate_projector(triangle, fragment, 0);
                        });
    }
  }
  return samples;
}

scene::Projector side_projector() {
  scene::Projector p;
  p.name = "side";
  p.eye = {1.0, 1.0, -1.5};
  p.target = {0.0, -1.0, -2.5};
  p.fovy_deg = 60.0;
  p.aspect = 1.3;
  p.near = 0.2;
  p.far = 20.0;
  return p;
}

}  // namespace

TEST_CASE("uv, depth and projector coordinates are perspective-correct on a receding quad", "[interpolation]") {
  scene::Scene s = floor_scene();
  // Corners project exactly onto the pixel grid: (0,64), (64,64), (64,40), (0,40).
  s.objects.push_back(floor_quad(-1.0, -4.0, 1.0));
  s.projectors.push_back(side_projector());
  const glm::dmat4 view_projection = scene::camera_view_projection(s);
  const glm::dmat4 projector_matrix = scene::projector_texture_matrix(s.camera, s.projectors[0]);

  const auto samples = rasterize_all(s);
  REQUIRE(samples.size() == 64 * 24);  // rows 40..63, every column, the shared diagonal once
  for (const auto& [pixel, sample] : samples) {
    const auto [px, py] = pixel;
    INFO("pixel " << px << ", " << py);
    REQUIRE(sample.hits == 1);
    REQUIRE(py >= 40);
    const glm::dvec3 p = floor_point(s, px, py);
    const glm::dvec2 uv = floor_uv(p);
    CHECK(sample.uv.x == Approx(uv.x).margin(1e-9));
    CHECK(sample.uv.y == Approx(uv.y).margin(1e-9));
    const glm::dvec4 clip = view_projection * glm::dvec4(p, 1.0);
    CHECK(sample.depth == Approx((clip.z / clip.w + 1.0) / 2.0).margin(1e-12));
    const glm::dvec4 strq = projector_matrix * glm::dvec4(p, 1.0);
    for (int c = 0; c < 4; ++c) CHECK(sample.strq[c] == Approx(strq[c]).margin(1e-9));
  }
  // The test can tell: interpolating v linearly down the screen would be far off.
  const double v_linear = (64.0 - 50.5) / 24.0;
  CHECK(std::abs(samples.at({10, 50}).uv.y - v_linear) > 0.2);
}

TEST_CASE("a quad reaching behind the eye is clipped at the near plane and stays perspective-correct",
          "[interpolation][clip]") {
  scene::Scene s = floor_scene();
  s.objects.push_back(floor_quad(2.0, -4.0, 4.0));  // from behind the eye (z = 2) to z = -4
  const auto samples = rasterize_all(s);
  REQUIRE(!samples.empty());
  for (const auto& [pixel, sample] : samples) {
    const auto [px, py] = pixel;
    INFO("pixel " << px << ", " << py);
    REQUIRE(sample.hits == 1);
    const glm::dvec2 uv = floor_uv(floor_point(s, px, py));
    CHECK(sample.uv.x == Approx(uv.x).margin(1e-9));
    CHECK(sample.uv.y == Approx(uv.y).margin(1e-9));
  }
  // Every pixel whose ray meets the quad well inside its far corners is drawn.
  for (int py = 33; py < 64; ++py) {
    for (int px = 0; px < 64; ++px) {
      const glm::dvec3 p = floor_point(s, px, py);
      if (std::abs(p.x) < 3.9 && p.z > -3.9) CHECK(samples.count({px, py}) == 1);
    }
  }
}

TEST_CASE("clipping against near and far keeps the parts inside and interpolates attributes in clip space",
          "[clip]") {
  const auto vertex = [](double z, double w, double u) {
    fm::ClipVertex v;
    v.position = {0.0, 0.0, z, w};
    v.uv = {u, 0.0};
    v.projector = {glm::dvec4(u, 2 * u, 3 * u, 1.0)};
    return v;
  };
  SECTION("one vertex behind near: a quad, two triangles") {
    const fm::ClipTriangle t{vertex(-3.0, 1.0, 0.0), vertex(0.0, 1.0, 1.0), vertex(0.5, 1.0, 2.0)};
    const auto pieces = fm::clip_triangle(t);
    REQUIRE(pieces.size() == 2);
    // The new vertices lie on z = -w = -1, a third of the way along (0 -> 1) and
    // three sevenths of the way along (2 -> 0): u = 2/3 and u = 8/7.
    std::vector<double> on_plane;
    for (const auto& piece : pieces) {
      for (const auto& v : piece) {
        CHECK(v.position.z + v.position.w >= -1e-12);
        CHECK(v.projector[0].y == Approx(2.0 * v.uv.x));  // every attribute moves together
        if (std::abs(v.position.z + 1.0) < 1e-12) on_plane.push_back(v.uv.x);
      }
    }
    REQUIRE(!on_plane.empty());
    for (double u : on_plane) CHECK((u == Approx(2.0 / 3.0) || u == Approx(8.0 / 7.0)));
    CHECK(std::count_if(on_plane.begin(), on_plane.end(), [](double u) { return u == Approx(8.0 / 7.0); }) > 0);
    CHECK(std::count_if(on_plane.begin(), on_plane.end(), [](double u) { return u == Approx(2.0 / 3.0); }) > 0);
  }
  SECTION("two vertices beyond far: one triangle") {
    const fm::ClipTriangle t{vertex(0.0, 1.0, 0.0), vertex(3.0, 1.0, 1.0), vertex(5.0, 1.0, 2.0)};
    const auto pieces = fm::clip_triangle(t);
    REQUIRE(pieces.size() == 1);
    CHECK(pieces[0][1].position.z == Approx(1.0));
    CHECK(pieces[0][1].uv.x == Approx(1.0 / 3.0));
    CHECK(pieces[0][2].position.z == Approx(1.0));
    CHECK(pieces[0][2].uv.x == Approx(2.0 / 5.0));
  }
  SECTION("wholly outside: nothing; wholly inside: unchanged") {
    CHECK(fm::clip_triangle({vertex(-2, 1, 0), vertex(-3, 1, 0), vertex(-4, 1, 0)}).empty());
    CHECK(fm::clip_triangle({vertex(0, 1, 0), vertex(0.5, 1, 1), vertex(-0.5, 1, 2)}).size() == 1);
  }
}

TEST_CASE("back culling drops triangles that are clockwise in the output image", "[culling]") {
  scene::Scene s = spanlight::test::empty_scene(16, 16, {0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60.0, 1.0, 10.0);
  scene::Object facing;  // counter-clockwise seen from +z, where the eye is: a front face
  facing.name = "facing";
  facing.mesh.positions = {{-2, -2, 0}, {2, -2, 0}, {0, 2, 0}};
  facing.mesh.uvs.assign(3, glm::dvec2(0.0));
  facing.mesh.triangles = {{0, 1, 2}};
  facing.cull = scene::Cull::back;
  scene::Object turned_away = facing;
  turned_away.name = "turned_away";
  turned_away.mesh.triangles = {{0, 2, 1}};

  const auto drawn_pixels = [&](const scene::Object& object) {
    scene::Scene one = s;
    one.objects = {object};
    const fm::FloatFrame frame = fm::render_float(one);
    return std::count(frame.object.begin(), frame.object.end(), 0);
  };
  CHECK(drawn_pixels(facing) > 20);
  CHECK(drawn_pixels(turned_away) == 0);
  turned_away.cull = scene::Cull::none;
  CHECK(drawn_pixels(turned_away) == drawn_pixels(facing));
}

TEST_CASE("the nearest surface wins, and at equal depth the one drawn first", "[depth]") {
  scene::Scene s = spanlight::test::empty_scene(16, 16, {0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 60.0, 1.0, 10.0);
  const auto square = [](std::string name, double z, double half) {
    return quad(std::move(name), {glm::dvec3(-half, -half, z), glm::dvec3(half, -half, z), glm::dvec3(half, half, z),
                                  glm::dvec3(-half, half, z)});
  };
  const std::size_t middle = 8 * 16 + 8;
  s.objects = {square("far", 0.0, 2.0), square("near", 1.0, 0.5)};
  CHECK(fm::render_float(s).object[middle] == 1);
  s.objects = {square("near", 1.0, 0.5), square("far", 0.0, 2.0)};
  CHECK(fm::render_float(s).object[middle] == 0);
  s.objects = {square("first", 0.0, 4.0), square("second", 0.0, 4.0)};
  const fm::FloatFrame frame = fm::render_float(s);
  CHECK(frame.object[middle] == 0);
  CHECK(frame.depth[middle] < 1.0);
  CHECK(frame.depth[0] < 1.0);  // the squares fill the frame (it spans +-2.9 at z = 0)
}

TEST_CASE("a checker texture shows the texel the analytic uv falls in", "[interpolation][sample]") {
  scene::Scene s = floor_scene();
  s.ambient = glm::dvec3(1.0);
  s.textures.push_back(spanlight::test::texture("checker", spanlight::test::checker_image(8), scene::Filter::nearest,
                                                scene::Wrap::repeat));
  s.objects.push_back(floor_quad(-1.0, -4.0, 1.0));
  s.objects[0].texture = 0;
  const fm::FloatFrame frame = fm::render_float(s);
  int checked = 0;
  for (int py = 40; py < 64; ++py) {
    for (int px = 0; px < 64; ++px) {
      const glm::dvec2 texel_position = floor_uv(floor_point(s, px, py)) * 8.0;
      const glm::dvec2 cell = glm::floor(texel_position);
      const glm::dvec2 inside = texel_position - cell;
      if (glm::any(glm::lessThan(inside, glm::dvec2(0.02))) || glm::any(glm::greaterThan(inside, glm::dvec2(0.98)))) {
        continue;  // too near a cell border to call by hand
      }
      const int column = static_cast<int>(cell.x);
      const int row_from_top = 7 - static_cast<int>(cell.y);  // t = 0 is the bottom row
      const std::uint8_t expected = (column + row_from_top) % 2 == 0 ? 255 : 0;
      INFO("pixel " << px << ", " << py);
      CHECK(frame.rgb[static_cast<std::size_t>(py * 64 + px) * 3] == expected);
      ++checked;
    }
  }
  CHECK(checked > 1000);
}
