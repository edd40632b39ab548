// Texture sampling against texels worked out by hand: t = 0 is the bottom row
// of the image, texel centres sit at half-integers, and the wrap modes.
#include <catch2/catch.hpp>

#include "float_model/sample.hpp"
#include "test_scenes.hpp"

namespace fm = spanlight::float_model;
namespace scene = spanlight::scene;
using scene::Wrap;

namespace {

// 4 x 2 texels. Red = 20 + 10 * column + 100 * row_from_top, green = column,
// blue = row_from_top (rows as stored in the file: top row first).
scene::Image numbered_image() {
  scene::Image image{4, 2, {}};
  for (int row = 0; row < 2; ++row) {
    for (int column = 0; column < 4; ++column) {
      image.rgb.push_back(static_cast<std::uint8_t>(20 + 10 * column + 100 * row));
      image.rgb.push_back(static_cast<std::uint8_t>(column));
      image.rgb.push_back(static_cast<std::uint8_t>(row));
    }
  }
  return image;
}

// Red of the texel at (column, row counted from the bottom), in bytes.
double red(int column, int row_from_bottom) { return 20 + 10 * column + 100 * (1 - row_from_bottom); }

double red_of(glm::dvec3 sample) { return sample.r * 255.0; }

}  // namespace

TEST_CASE("nearest reads the texel containing uv, with t = 0 at the bottom of the image", "[sample]") {
  const scene::Image image = numbered_image();
  const glm::dvec3 bottom_left = fm::sample_nearest(image, Wrap::repeat, {0.1, 0.1});
  CHECK(red_of(bottom_left) == Approx(120.0));  // column 0, bottom row = row 1 of the file
  CHECK(bottom_left.b * 255.0 == Approx(1.0));
  CHECK(red_of(fm::sample_nearest(image, Wrap::repeat, {0.9, 0.9})) == Approx(50.0));  // column 3, top row
  CHECK(red_of(fm::sample_nearest(image, Wrap::repeat, {0.3, 0.6})) == Approx(30.0));  // column 1, top row
  CHECK(red_of(fm::sample_nearest(image, Wrap::repeat, {0.25, 0.5})) == Approx(30.0)); // edges belong to the upper texel
}

TEST_CASE("nearest wraps indices: repeat takes them modulo the size, clamp to the edge, border is black",
          "[sample]") {
  const scene::Image image = numbered_image();
  // u = 1 is column 4, one past the last.
  CHECK(red_of(fm::sample_nearest(image, Wrap::repeat, {1.0, 0.25})) == Approx(red(0, 0)));
  CHECK(red_of(fm::sample_nearest(image, Wrap::clamp, {1.0, 0.25})) == Approx(red(3, 0)));
  CHECK(fm::sample_nearest(image, Wrap::border, {1.0, 0.25}) == glm::dvec3(0.0));
  // u = -0.1 is column -1.
  CHECK(red_of(fm::sample_nearest(image, Wrap::repeat, {-0.1, 0.25})) == Approx(red(3, 0)));
  CHECK(red_of(fm::sample_nearest(image, Wrap::clamp, {-0.1, 0.25})) == Approx(red(0, 0)));
  CHECK(fm::sample_nearest(image, Wrap::border, {-0.1, 0.25}) == glm::dvec3(0.0));
  // v = 1 is row 2 from the bottom, one past the top.
  CHECK(red_of(fm::sample_nearest(image, Wrap::repeat, {0.1, 1.0})) == Approx(red(0, 0)));
  CHECK(red_of(fm::sample_nearest(image, Wrap::clamp, {0.1, 1.0})) == Approx(red(0, 1)));
  CHECK(fm::sample_nearest(image, Wrap::border, {0.1, 1.0}) == glm::dvec3(0.0));
  // Far off: column floor(-2.1 * 4) = -9, which is 3 modulo 4.
  CHECK(red_of(fm::sample_nearest(image, Wrap::repeat, {-2.1, 0.25})) == Approx(red(3, 0)));
}

TEST_CASE("bilinear blends the four texels around uv with texel centres at half-integers", "[sample]") {
  const scene::Image image = numbered_image();
  SECTION("at a texel centre it is that texel") {
    for (int column = 0; column < 4; ++column) {
      for (int row = 0; row < 2; ++row) {
        const glm::dvec2 uv((column + 0.5) / 4.0, (row + 0.5) / 2.0);
        CHECK(red_of(fm::sample_bilinear(image, Wrap::border, uv)) == Approx(red(column, row)));
      }
    }
  }
  SECTION("halfway between four texels it is their mean") {
    const double mean = (red(1, 0) + red(2, 0) + red(1, 1) + red(2, 1)) / 4.0;
    CHECK(red_of(fm::sample_bilinear(image, Wrap::repeat, {0.5, 0.5})) == Approx(mean));
  }
  SECTION("the weights are (1-fx)(1-fy), fx(1-fy), (1-fx)fy, fx fy") {
    // u = 0.3: x = 0.7 -> columns 0 and 1, fx = 0.7; v = 0.6: y = 0.7 -> rows 0 and 1 from the bottom.
    const double expected = 0.3 * 0.3 * red(0, 0) + 0.7 * 0.3 * red(1, 0) + 0.3 * 0.7 * red(0, 1) + 0.7 * 0.7 * red(1, 1);
    CHECK(red_of(fm::sample_bilinear(image, Wrap::repeat, {0.3, 0.6})) == Approx(expected));
  }
  SECTION("at the left edge: border blends toward black, clamp repeats the edge, repeat reaches across") {
    const glm::dvec2 uv(0.0, 0.25);  // x = -0.5: half column -1, half column 0; bottom row exactly
    CHECK(red_of(fm::sample_bilinear(image, Wrap::border, uv)) == Approx(0.5 * red(0, 0)));
    CHECK(red_of(fm::sample_bilinear(image, Wrap::clamp, uv)) == Approx(red(0, 0)));
    CHECK(red_of(fm::sample_bilinear(image, Wrap::repeat, uv)) == Approx(0.5 * red(0, 0) + 0.5 * red(3, 0)));
  }
  SECTION("in a corner, border keeps a quarter") {
    CHECK(red_of(fm::sample_bilinear(image, Wrap::border, {0.0, 0.0})) == Approx(0.25 * red(0, 0)));
  }
}

TEST_CASE("projector images are always sampled with a black border, whatever their wrap says", "[sample]") {
  const scene::Texture slide =
      spanlight::test::texture("slide", numbered_image(), scene::Filter::bilinear, Wrap::repeat);
  CHECK(red_of(fm::sample_projector_image(slide, {0.0, 0.25})) == Approx(0.5 * red(0, 0)));
  CHECK(red_of(fm::sample_texture(slide, {0.0, 0.25})) == Approx(0.5 * red(0, 0) + 0.5 * red(3, 0)));
  const scene::Texture nearest_slide =
      spanlight::test::texture("slide", numbered_image(), scene::Filter::nearest, Wrap::repeat);
  CHECK(fm::sample_projector_image(nearest_slide, {1.0, 0.5}) == glm::dvec3(0.0));
  CHECK(red_of(fm::sample_projector_image(nearest_slide, {0.99, 0.5})) == Approx(red(3, 1)));
}
