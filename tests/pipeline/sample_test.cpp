// sample.hpp against texels worked out by hand on a 4x4 texture.
//
// The texture, as stored (top row first), texel (column, row_from_top):
//   r = 17 * column + 68 * row_from_top   (0..255, every texel distinct)
//   g = 255 - r
//   b = 40 * column
// t = 0 is the BOTTOM row of the image, so row_from_bottom = 3 - row_from_top.
// Coordinates are in texels with `frac` sub-texel bits (frac = 8 unless said).
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "spanlight/sample.hpp"

using spanlight::Filter;
using spanlight::Rgb8;
using spanlight::TextureData;
using spanlight::Wrap;

namespace {

std::vector<std::uint8_t> make_texels() {
  std::vector<std::uint8_t> rgb;
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) {
      const int r = 17 * column + 68 * row;
      rgb.push_back(static_cast<std::uint8_t>(r));
      rgb.push_back(static_cast<std::uint8_t>(255 - r));
      rgb.push_back(static_cast<std::uint8_t>(40 * column));
    }
  }
  return rgb;
}

const std::vector<std::uint8_t>& texels() {
  static const std::vector<std::uint8_t> data = make_texels();
  return data;
}

TextureData tex(Filter filter, Wrap wrap) { return TextureData{texels().data(), 4, 4, filter, wrap}; }

// Texels * 256 (frac = 8).
constexpr std::int32_t at(double texels) { return static_cast<std::int32_t>(texels * 256.0); }

std::array<int, 3> rgb(Rgb8 c) { return {c.r, c.g, c.b}; }

}  // namespace

TEST_CASE("nearest reads the texel containing the point, with t = 0 the bottom row", "[sample]") {
  const TextureData t = tex(Filter::nearest, Wrap::clamp);
  // u = 1.5, v = 0.5 texels: column 1, row_from_bottom 0 = row_from_top 3:
  // r = 17 + 204 = 221, g = 34, b = 40.
  CHECK(rgb(spanlight::sample_nearest(t, at(1.5), at(0.5), 8, Wrap::clamp)) == std::array<int, 3>{221, 34, 40});
  // v = 3.99 texels: the top row (row_from_top 0); u = 0: column 0 -> r 0, g 255, b 0.
  CHECK(rgb(spanlight::sample_nearest(t, 0, at(3.99), 8, Wrap::clamp)) == std::array<int, 3>{0, 255, 0});
  // u = 2.999..., v = 2.0 exactly: column 2, row_from_bottom 2 = row_from_top 1: r = 34 + 68 = 102.
  CHECK(rgb(spanlight::sample_nearest(t, at(3.0) - 1, at(2.0), 8, Wrap::clamp)) == std::array<int, 3>{102, 153, 80});
  // Other fraction widths read the same texel: frac 4 and frac 16 for u = 1.5, v = 0.5.
  CHECK(rgb(spanlight::sample_nearest(t, 24, 8, 4, Wrap::clamp)) == std::array<int, 3>{221, 34, 40});
  CHECK(rgb(spanlight::sample_nearest(t, 3 << 15, 1 << 15, 16, Wrap::clamp)) == std::array<int, 3>{221, 34, 40});
}

TEST_CASE("nearest wraps with repeat, clamps with clamp, and is black outside with border", "[sample]") {
  const TextureData t = tex(Filter::nearest, Wrap::repeat);
  // u = -0.5 texel: column -1 -> repeat 3, clamp 0, border black; v = 0.5: row_from_top 3.
  //   column 3, row 3: r = 51 + 204 = 255, g 0, b 120; column 0, row 3: r = 204, g 51, b 0.
  CHECK(rgb(spanlight::sample_nearest(t, at(-0.5), at(0.5), 8, Wrap::repeat)) == std::array<int, 3>{255, 0, 120});
  CHECK(rgb(spanlight::sample_nearest(t, at(-0.5), at(0.5), 8, Wrap::clamp)) == std::array<int, 3>{204, 51, 0});
  CHECK(rgb(spanlight::sample_nearest(t, at(-0.5), at(0.5), 8, Wrap::border)) == std::array<int, 3>{0, 0, 0});
  // u = 5.25 texels: column 5 -> repeat 1, clamp 3, border black; v = 9.5: row_from_bottom 9
  // -> repeat 1 (row_from_top 2), clamp 3 (row_from_top 0).
  //   repeat: column 1, row 2: r = 17 + 136 = 153, g 102, b 40; clamp: column 3, row 0: r 51, g 204, b 120.
  CHECK(rgb(spanlight::sample_nearest(t, at(5.25), at(9.5), 8, Wrap::repeat)) == std::array<int, 3>{153, 102, 40});
  CHECK(rgb(spanlight::sample_nearest(t, at(5.25), at(9.5), 8, Wrap::clamp)) == std::array<int, 3>{51, 204, 120});
  CHECK(rgb(spanlight::sample_nearest(t, at(5.25), at(9.5), 8, Wrap::border)) == std::array<int, 3>{0, 0, 0});
  // Far negative repeats too: u = -7.5 -> column -8 -> 0; v = -3.5 -> row_from_bottom -4 -> 0 (row_from_top 3).
  CHECK(rgb(spanlight::sample_nearest(t, at(-7.5), at(-3.5), 8, Wrap::repeat)) == std::array<int, 3>{204, 51, 0});
}

TEST_CASE("bilinear puts texel centres at half-integers: a centre reads its texel alone", "[sample]") {
  const TextureData t = tex(Filter::bilinear, Wrap::clamp);
  // u = 1.5, v = 2.5: x = 1.0, y = 2.0 after the half-texel shift, weights 0:
  // column 1, row_from_bottom 2 = row_from_top 1: r = 17 + 68 = 85, g 170, b 40.
  CHECK(rgb(spanlight::sample_bilinear(t, at(1.5), at(2.5), 8, Wrap::clamp)) == std::array<int, 3>{85, 170, 40});
  // The same at frac 12 and frac 4.
  CHECK(rgb(spanlight::sample_bilinear(t, 6144, 10240, 12, Wrap::clamp)) == std::array<int, 3>{85, 170, 40});
  CHECK(rgb(spanlight::sample_bilinear(t, 24, 40, 4, Wrap::clamp)) == std::array<int, 3>{85, 170, 40});
}

TEST_CASE("bilinear blends the four texels around the point with 8-bit weights, rounding to nearest", "[sample]") {
  const TextureData t = tex(Filter::bilinear, Wrap::clamp);
  // Half way across in u only: u = 2.0, v = 0.5 -> x = 1.5 (columns 1 and 2, fx = 128), y = 0 (fy = 0),
  // row_from_top 3: r (221 + 238) / 2 = 229.5 -> 230 (halves round up: + 32768 before >> 16),
  // g (34 + 17) / 2 = 25.5 -> 26, b (40 + 80) / 2 = 60.
  CHECK(rgb(spanlight::sample_bilinear(t, at(2.0), at(0.5), 8, Wrap::clamp)) == std::array<int, 3>{230, 26, 60});

  // u = 1.75, v = 1.25: x = 1.25 -> columns 1, 2 with fx = 64; y = 0.75 -> rows_from_bottom 0, 1 with fy = 192.
  // rows_from_bottom 0, 1 are rows_from_top 3, 2. Weights (of 65536):
  //   w00 = 192 * 64 = 12288 (col 1, rfb 0), w10 = 64 * 64 = 4096 (col 2, rfb 0),
  //   w01 = 192 * 192 = 36864 (col 1, rfb 1), w11 = 64 * 192 = 12288 (col 2, rfb 1).
  // r: 221, 238, 153, 170 -> 2715648 + 974848 + 5640192 + 2088960 = 11419648; + 32768 -> >> 16 = 174.75 -> 174
  // g: 34, 17, 102, 85    -> 417792 + 69632 + 3760128 + 1044480 = 5292032;    + 32768 -> >> 16 = 81.25 -> 81
  // b: 40, 80, 40, 80     -> 491520 + 327680 + 1474560 + 983040 = 3276800;    + 32768 -> >> 16 = 50.5 -> 50
  CHECK(rgb(spanlight::sample_bilinear(t, at(1.75), at(1.25), 8, Wrap::clamp)) == std::array<int, 3>{174, 81, 50});

  // Weights keep 8 bits, truncated: 1/512 texel past a centre (frac 16) still reads the centre's texel alone.
  // u = 1.5 + 2^-9, v = 2.5: x = 1 + 2^-9 -> weight (x >> 8) & 255 = 0.
  CHECK(rgb(spanlight::sample_bilinear(t, 3 * 32768 + 128, 5 * 32768, 16, Wrap::clamp)) ==
        std::array<int, 3>{85, 170, 40});
  // ... and 1/256 texel past it takes weight 1/256 of the next column (column 2, row_from_top 1: r 102, g 153, b 80):
  // r (85 * 255 + 102) * 256 / 65536 = 85.07 -> 85, g (170 * 255 + 153) / 256 = 169.93 -> 170, b (40 * 255 + 80) / 256 = 40.16 -> 40.
  CHECK(rgb(spanlight::sample_bilinear(t, 3 * 32768 + 256, 5 * 32768, 16, Wrap::clamp)) ==
        std::array<int, 3>{85, 170, 40});
  // A quarter past at frac 16: x = 1.25 -> fx = 64; y = 2.0 -> fy = 0, row_from_top 1:
  // r (85 * 192 + 102 * 64) / 256 = 89.25 -> 89, g (170 * 192 + 153 * 64) / 256 = 165.75 -> 166, b 50.
  CHECK(rgb(spanlight::sample_bilinear(t, 7 * 16384, 5 * 32768, 16, Wrap::clamp)) == std::array<int, 3>{89, 166, 50});
}

TEST_CASE("bilinear at the texture's edge follows the wrap mode: clamp, repeat, black border", "[sample]") {
  // u = 0, v = 0.5: x = -0.5 -> columns -1 and 0 with fx = 128; y = 0, row_from_top 3.
  // clamp: both column 0 -> r 204, g 51, b 0.
  CHECK(rgb(spanlight::sample_bilinear(tex(Filter::bilinear, Wrap::clamp), 0, at(0.5), 8, Wrap::clamp)) ==
        std::array<int, 3>{204, 51, 0});
  // repeat: columns 3 and 0 -> r (255 + 204) / 2 = 229.5 -> 230, g (0 + 51) / 2 = 25.5 -> 26, b (120 + 0) / 2 = 60.
  CHECK(rgb(spanlight::sample_bilinear(tex(Filter::bilinear, Wrap::repeat), 0, at(0.5), 8, Wrap::repeat)) ==
        std::array<int, 3>{230, 26, 60});
  // border: black and column 0 -> r 102, g 25.5 -> 26, b 0.
  CHECK(rgb(spanlight::sample_bilinear(tex(Filter::bilinear, Wrap::border), 0, at(0.5), 8, Wrap::border)) ==
        std::array<int, 3>{102, 26, 0});
  // Corner, border: u = v = 0.25 -> x = y = -0.25, fx = fy = 192 (x0 = y0 = -1): only texel
  // (column 0, row_from_bottom 0) = r 204, g 51, b 0 is inside, weight 192 * 192 = 36864:
  // r 204 * 36864 / 65536 = 114.75 -> 115, g 51 * 0.5625 = 28.69 -> 29, b 0.
  CHECK(rgb(spanlight::sample_bilinear(tex(Filter::bilinear, Wrap::border), at(0.25), at(0.25), 8, Wrap::border)) ==
        std::array<int, 3>{115, 29, 0});
  // Top edge with repeat: v = 4.0 -> y = 3.5: rows_from_bottom 3 and 4 -> 0, i.e. rows_from_top 0 and 3,
  // fy = 128; u = 0.5 (column 0): r (0 + 204) / 2 = 102, g (255 + 51) / 2 = 153, b 0.
  CHECK(rgb(spanlight::sample_bilinear(tex(Filter::bilinear, Wrap::repeat), at(0.5), at(4.0), 8, Wrap::repeat)) ==
        std::array<int, 3>{102, 153, 0});
}

TEST_CASE("sample<> uses the texture's own filter, and nearest alone when bilinear is compiled out", "[sample]") {
  // u = 2.0, v = 0.5: bilinear blends columns 1 and 2 (230, 26, 60, as above); nearest reads column 2,
  // row_from_top 3: r = 34 + 204 = 238, g 17, b 80.
  CHECK(rgb(spanlight::sample<true>(tex(Filter::bilinear, Wrap::clamp), at(2.0), at(0.5), 8, Wrap::clamp)) ==
        std::array<int, 3>{230, 26, 60});
  CHECK(rgb(spanlight::sample<true>(tex(Filter::nearest, Wrap::clamp), at(2.0), at(0.5), 8, Wrap::clamp)) ==
        std::array<int, 3>{238, 17, 80});
  CHECK(rgb(spanlight::sample<false>(tex(Filter::bilinear, Wrap::clamp), at(2.0), at(0.5), 8, Wrap::clamp)) ==
        std::array<int, 3>{238, 17, 80});
}

TEST_CASE("the run loop's repeat-wrapped bilinear fetch equals the general one to the bit", "[sample]") {
  // sample_bilinear_packed (the modulate and fused passes' fast path) restates
  // sample16_bilinear_as<Wrap::repeat> with per-run constants; the passes rely on
  // it giving the same bytes. Random coordinates over many wraps, every size
  // combination of 1..64 and all the sub-texel precisions it accepts.
  std::mt19937 random(0x5a3e1e);
  for (const int width : {1, 2, 4, 16, 64}) {
    for (const int height : {1, 4, 32}) {
      std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width * height * 3));
      for (std::uint8_t& c : rgb) c = static_cast<std::uint8_t>(random());
      const TextureData tex{rgb.data(), static_cast<std::uint16_t>(width), static_cast<std::uint16_t>(height),
                            Filter::bilinear, Wrap::repeat};
      for (const int frac : {8, 12, 16, 20}) {
        REQUIRE(spanlight::RepeatTexture::fits(frac));
        const spanlight::RepeatTexture fast(tex, frac);
        const std::int32_t range = 1 << (frac + 8);  // +-256 texels: many wraps both ways
        std::uniform_int_distribution<std::int32_t> coordinate(-range, range);
        for (int n = 0; n < 2000; ++n) {
          const std::int32_t u = coordinate(random), v = coordinate(random);
          const Rgb8 expected = spanlight::round_texel(spanlight::sample16_bilinear_as<Wrap::repeat>(tex, u, v, frac));
          const Rgb8 got = spanlight::unpack_rgb(spanlight::sample_bilinear_packed(fast, u, v));
          INFO("size " << width << "x" << height << ", frac " << frac << ", u " << u << ", v " << v);
          REQUIRE(int{got.r} == int{expected.r});
          REQUIRE(int{got.g} == int{expected.g});
          REQUIRE(int{got.b} == int{expected.b});
        }
      }
    }
  }
  CHECK_FALSE(spanlight::RepeatTexture::fits(7));  // fewer sub-texel bits take the general path
}
