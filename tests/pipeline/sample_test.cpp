// 4_pixel/texture.hpp against texels worked out by hand on a 4x4 texture, and
// its exact 8-bit bilinear blends (lanes, dual products) against a scalar reference, bit for bit.
//
// The texture, as stored in the scene file (top row first), texel (column, row_from_top):
//   r = 17 * column + 68 * row_from_top   (0..255, every texel distinct)
//   g = 255 - r
//   b = 40 * column
// t = 0 is the BOTTOM row of the image, so row_from_bottom = 3 - row_from_top.
// Coordinates are in texels with `frac` sub-texel bits (frac = 8 unless said),
// or, for a repeating texture, a fraction of its size in 32 bits (walk.hpp's
// StepScale); bilinear coordinates already point half a texel back.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "prepare/prepare.hpp"
#include "spanlight/4_pixel/surface.hpp"
#include "spanlight/4_pixel/texture.hpp"

using spanlight::Colour;
using spanlight::TexelGrid;
using spanlight::Wrap;

namespace {

spanlight::scene::Image ramp_image() {
  spanlight::scene::Image image{4, 4, {}};
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) {
      const int r = 17 * column + 68 * row;
      image.rgb.push_back(static_cast<std::uint8_t>(r));
      image.rgb.push_back(static_cast<std::uint8_t>(255 - r));
      image.rgb.push_back(static_cast<std::uint8_t>(40 * column));
    }
  }
  return image;
}

// The 4x4 texture in the sampler's layout (framed for `wrap`), as prepare bakes it.
struct Baked {
  std::vector<std::uint32_t> framed;
  spanlight::TextureLevel level;
  explicit Baked(Wrap wrap) : framed(spanlight::prepare::framed_texels(ramp_image(), wrap)) {
    const std::uint16_t stride = 4 + 2 * spanlight::texture_frame;
    level = {framed.data() + stride * spanlight::texture_frame + spanlight::texture_frame, 4, 4, stride};
  }
  TexelGrid grid(int frac = 8) const { return spanlight::texel_grid(level, frac); }
};

constexpr std::int32_t at(double texels) { return static_cast<std::int32_t>(texels * 256.0); }
// A repeating coordinate: `texels` as a fraction of a 4-texel side in 32 bits (wrapping).
std::uint32_t rep(double texels) {
  return static_cast<std::uint32_t>(static_cast<std::int64_t>(std::floor(texels / 4.0 * 4294967296.0)));
}

std::array<int, 3> rgb(Colour c) {
  return {static_cast<int>(spanlight::red(c)), static_cast<int>(spanlight::green(c)), static_cast<int>(spanlight::blue(c))};
}

}  // namespace

TEST_CASE("nearest reads the texel containing the point, with t = 0 the bottom row", "[sample]") {
  const Baked t(Wrap::clamp);
  // u = 1.5, v = 0.5 texels: column 1, row_from_bottom 0 = row_from_top 3:
  // r = 17 + 204 = 221, g = 34, b = 40.
  CHECK(rgb(spanlight::nearest<Wrap::clamp>(t.grid(), at(1.5), at(0.5))) == std::array<int, 3>{221, 34, 40});
  // v = 3.99 texels: the top row (row_from_top 0); u = 0: column 0 -> r 0, g 255, b 0.
  CHECK(rgb(spanlight::nearest<Wrap::clamp>(t.grid(), 0, at(3.99))) == std::array<int, 3>{0, 255, 0});
  // u = 2.999..., v = 2.0 exactly: column 2, row_from_bottom 2 = row_from_top 1: r = 34 + 68 = 102.
  CHECK(rgb(spanlight::nearest<Wrap::clamp>(t.grid(), at(3.0) - 1, at(2.0))) == std::array<int, 3>{102, 153, 80});
  // Other fraction widths read the same texel: frac 12 and frac 16 for u = 1.5, v = 0.5.
  CHECK(rgb(spanlight::nearest<Wrap::clamp>(t.grid(12), 3 << 11, 1 << 11)) == std::array<int, 3>{221, 34, 40});
  CHECK(rgb(spanlight::nearest<Wrap::clamp>(t.grid(16), 3 << 15, 1 << 15)) == std::array<int, 3>{221, 34, 40});
}

TEST_CASE("nearest wraps with repeat, clamps with clamp, and is black outside with border", "[sample]") {
  const Baked repeat(Wrap::repeat), clamp(Wrap::clamp), border(Wrap::border);
  // u = -0.5 texel: column -1 -> repeat 3, clamp 0, border black; v = 0.5: row_from_top 3.
  //   column 3, row 3: r = 51 + 204 = 255, g 0, b 120; column 0, row 3: r = 204, g 51, b 0.
  CHECK(rgb(spanlight::nearest_repeat(repeat.grid(), rep(-0.5), rep(0.5))) == std::array<int, 3>{255, 0, 120});
  CHECK(rgb(spanlight::nearest<Wrap::clamp>(clamp.grid(), at(-0.5), at(0.5))) == std::array<int, 3>{204, 51, 0});
  CHECK(rgb(spanlight::nearest<Wrap::border>(border.grid(), at(-0.5), at(0.5))) == std::array<int, 3>{0, 0, 0});
  // u = 5.25 texels: column 5 -> repeat 1, clamp 3, border black; v = 9.5: row_from_bottom 9
  // -> repeat 1 (row_from_top 2), clamp 3 (row_from_top 0).
  //   repeat: column 1, row 2: r = 17 + 136 = 153, g 102, b 40; clamp: column 3, row 0: r 51, g 204, b 120.
  CHECK(rgb(spanlight::nearest_repeat(repeat.grid(), rep(5.25), rep(9.5))) == std::array<int, 3>{153, 102, 40});
  CHECK(rgb(spanlight::nearest<Wrap::clamp>(clamp.grid(), at(5.25), at(9.5))) == std::array<int, 3>{51, 204, 120});
  CHECK(rgb(spanlight::nearest<Wrap::border>(border.grid(), at(5.25), at(9.5))) == std::array<int, 3>{0, 0, 0});
  // Far negative repeats too: u = -7.5 -> column -8 -> 0; v = -3.5 -> row_from_bottom -4 -> 0 (row_from_top 3).
  CHECK(rgb(spanlight::nearest_repeat(repeat.grid(), rep(-7.5), rep(-3.5))) == std::array<int, 3>{204, 51, 0});
}

TEST_CASE("bilinear puts texel centres at half-integers: a centre reads its texel alone", "[sample]") {
  const Baked t(Wrap::clamp);
  // u = 1.5, v = 2.5: x = 1.0, y = 2.0 after the half-texel shift, weights 0:
  // column 1, row_from_bottom 2 = row_from_top 1: r = 17 + 68 = 85, g 170, b 40.
  CHECK(rgb(spanlight::bilinear_clamp(t.grid(), at(1.0), at(2.0))) == std::array<int, 3>{85, 170, 40});
  // The same at frac 12 and frac 16.
  CHECK(rgb(spanlight::bilinear_clamp(t.grid(12), 4096, 8192)) == std::array<int, 3>{85, 170, 40});
  CHECK(rgb(spanlight::bilinear_clamp(t.grid(16), 65536, 131072)) == std::array<int, 3>{85, 170, 40});
  // And the surface's step scale sets the half-texel shift for a bilinear texture, none for nearest.
  const spanlight::TextureData bilinear{&t.level, 1, spanlight::Filter::bilinear, Wrap::clamp};
  const spanlight::TextureData nearest{&t.level, 1, spanlight::Filter::nearest, Wrap::clamp};
  spanlight::ObjectData object{};
  object.texture = 0;
  object.uv_frac_bits = 8;
  object.color[0] = object.color[1] = object.color[2] = 255;
  const spanlight::Surface b = spanlight::surface_of(object, &bilinear), n = spanlight::surface_of(object, &nearest);
  CHECK(b.kind == spanlight::SurfaceKind::bilinear_clamp);
  CHECK(n.kind == spanlight::SurfaceKind::nearest_clamp);
  CHECK(b.scale.offset[0] == -128);
  CHECK(b.scale.offset[1] == -128);
  CHECK(n.scale.offset[0] == 0);
  CHECK_FALSE(b.tinted);
}

TEST_CASE("bilinear blends the four texels around the point with 8-bit weights, rounding to nearest", "[sample]") {
  const Baked t(Wrap::clamp);
  // Half way across in u only: u = 2.0, v = 0.5 -> x = 1.5 (columns 1 and 2, fx = 128), y = 0 (fy = 0),
  // row_from_top 3: r (221 + 238) / 2 = 229.5 -> 230 (halves round up: + 32768 before >> 16),
  // g (34 + 17) / 2 = 25.5 -> 26, b (40 + 80) / 2 = 60.
  CHECK(rgb(spanlight::bilinear_clamp(t.grid(), at(1.5), at(0.0))) == std::array<int, 3>{230, 26, 60});

  // u = 1.75, v = 1.25: x = 1.25 -> columns 1, 2 with fx = 64; y = 0.75 -> rows_from_bottom 0, 1 with fy = 192.
  // rows_from_bottom 0, 1 are rows_from_top 3, 2. Weights (of 65536):
  //   w00 = 192 * 64 = 12288 (col 1, rfb 0), w10 = 64 * 64 = 4096 (col 2, rfb 0),
  //   w01 = 192 * 192 = 36864 (col 1, rfb 1), w11 = 64 * 192 = 12288 (col 2, rfb 1).
  // r: 221, 238, 153, 170 -> 2715648 + 974848 + 5640192 + 2088960 = 11419648; + 32768 -> >> 16 = 174.75 -> 174
  // g: 34, 17, 102, 85    -> 417792 + 69632 + 3760128 + 1044480 = 5292032;    + 32768 -> >> 16 = 81.25 -> 81
  // b: 40, 80, 40, 80     -> 491520 + 327680 + 1474560 + 983040 = 3276800;    + 32768 -> >> 16 = 50.5 -> 50
  CHECK(rgb(spanlight::bilinear_clamp(t.grid(), at(1.25), at(0.75))) == std::array<int, 3>{174, 81, 50});

  // Weights keep 8 bits, truncated: 1/512 texel past a centre (frac 16) still reads the centre's texel alone.
  CHECK(rgb(spanlight::bilinear_clamp(t.grid(16), 65536 + 128, 2 * 65536)) == std::array<int, 3>{85, 170, 40});
  // ... and 1/256 texel past it takes weight 1/256 of the next column (column 2, row_from_top 1: r 102, g 153, b 80):
  // r (85 * 255 + 102) / 256 = 85.07 -> 85, g (170 * 255 + 153) / 256 = 169.93 -> 170, b (40 * 255 + 80) / 256 = 40.16 -> 40.
  CHECK(rgb(spanlight::bilinear_clamp(t.grid(16), 65536 + 256, 2 * 65536)) == std::array<int, 3>{85, 170, 40});
  // A quarter past at frac 16: x = 1.25 -> fx = 64; y = 2.0 -> fy = 0, row_from_top 1:
  // r (85 * 192 + 102 * 64) / 256 = 89.25 -> 89, g (170 * 192 + 153 * 64) / 256 = 165.75 -> 166, b 50.
  CHECK(rgb(spanlight::bilinear_clamp(t.grid(16), 81920, 2 * 65536)) == std::array<int, 3>{89, 166, 50});
}

TEST_CASE("bilinear at the texture's edge follows the wrap mode: clamp, repeat, black border", "[sample]") {
  const Baked repeat(Wrap::repeat), clamp(Wrap::clamp), border(Wrap::border);
  // u = 0, v = 0.5: x = -0.5 -> columns -1 and 0 with fx = 128; y = 0, row_from_top 3.
  // clamp: both column 0 -> r 204, g 51, b 0.
  CHECK(rgb(spanlight::bilinear_clamp(clamp.grid(), at(-0.5), 0)) == std::array<int, 3>{204, 51, 0});
  // repeat: columns 3 and 0 -> r (255 + 204) / 2 = 229.5 -> 230, g (0 + 51) / 2 = 25.5 -> 26, b (120 + 0) / 2 = 60.
  CHECK(rgb(spanlight::bilinear_repeat(repeat.grid(), rep(-0.5), 0)) == std::array<int, 3>{230, 26, 60});
  // border: black and column 0 -> r 102, g 25.5 -> 26, b 0.
  CHECK(rgb(spanlight::bilinear_border(border.grid(), at(-0.5), 0)) == std::array<int, 3>{102, 26, 0});
  // Corner, border: u = v = 0.25 -> x = y = -0.25, fx = fy = 192 (x0 = y0 = -1): only texel
  // (column 0, row_from_bottom 0) = r 204, g 51, b 0 is inside, weight 192 * 192 = 36864:
  // r 204 * 36864 / 65536 = 114.75 -> 115, g 51 * 0.5625 = 28.69 -> 29, b 0.
  CHECK(rgb(spanlight::bilinear_border(border.grid(), at(-0.25), at(-0.25))) == std::array<int, 3>{115, 29, 0});
  // Top edge with repeat: v = 4.0 -> y = 3.5: rows_from_bottom 3 and 4 -> 0, i.e. rows_from_top 0 and 3,
  // fy = 128; u = 0.5 (column 0): r (0 + 204) / 2 = 102, g (255 + 51) / 2 = 153, b 0.
  CHECK(rgb(spanlight::bilinear_repeat(repeat.grid(), 0, rep(3.5))) == std::array<int, 3>{102, 153, 0});
  // Far beyond the clamp edge: the edge texel alone (column 3, row_from_top 0: r 51, g 204, b 120).
  CHECK(rgb(spanlight::bilinear_clamp(clamp.grid(), at(1000.0), at(1000.0))) == std::array<int, 3>{51, 204, 120});
}

TEST_CASE("both bilinear blends, lanes and dual products, equal the scalar blend round(sum c w / 2^16) bit for bit, "
          "rounded and unrounded",
          "[sample]") {
  // Every weight pair (fx, fy) in [0, 255]^2 on texel sets chosen to reach the
  // lanes' limits (all 255, all 0, one corner 255) and at random. A lane carry
  // or a wrong rounding shows as a one-level difference.
  std::independent_bits_engine<std::mt19937, 32, std::uint32_t> random(0x5eedb11);  // 32-bit results: the same sequence
  std::vector<std::array<std::uint32_t, 4>> sets = {{0x00FFFFFFu, 0x00FFFFFFu, 0x00FFFFFFu, 0x00FFFFFFu},
                                                    {0, 0, 0, 0},
                                                    {0x00FFFFFFu, 0, 0, 0},
                                                    {0, 0, 0, 0x00FFFFFFu},
                                                    {0x00FF00FFu, 0x0000FF00u, 0x00FF00FFu, 0x0000FF00u}};
  const int random_sets = 12;
  for (int n = 0; n < random_sets; ++n)
    sets.push_back({random() & 0x00FFFFFFu, random() & 0x00FFFFFFu, random() & 0x00FFFFFFu, random() & 0x00FFFFFFu});
  long long compared = 0, mismatches = 0;
  for (const auto& t : sets) {
    for (std::uint32_t fy = 0; fy < 256; ++fy) {
      for (std::uint32_t fx = 0; fx < 256; ++fx) {
        const spanlight::Taps taps{t[0], t[1], t[2], t[3], fx, fy};
        const spanlight::BilinearSums s = spanlight::bilinear_sums(taps);
        const Colour rounded = spanlight::round_sums(s);
        const spanlight::Texel16 raw = spanlight::unrounded(s);
        // The dual-product form (Cortex-M4/M7's, here through the lanes' portable forms), plus 0 and
        // plus the rounding half; firmware.blend_check runs it on the targets' instructions.
        const spanlight::Texel16 dots = spanlight::bilinear_dot_sums(taps, 0), dots_half = spanlight::bilinear_dot_sums(taps, 1u << 15);
        const std::uint32_t w[4] = {(256 - fx) * (256 - fy), fx * (256 - fy), (256 - fx) * fy, fx * fy};
        std::uint32_t sum[3] = {0, 0, 0};
        for (int k = 0; k < 4; ++k)
          for (int c = 0; c < 3; ++c) sum[c] += ((t[static_cast<std::size_t>(k)] >> (16 - 8 * c)) & 255u) * w[k];
        const std::uint32_t got_raw[3] = {raw.r, raw.g, raw.b};
        const std::array<int, 3> got = rgb(rounded);
        ++compared;
        bool same = true;
        for (int c = 0; c < 3; ++c) {
          same = same && got_raw[c] == sum[c] && got[static_cast<std::size_t>(c)] == static_cast<int>((sum[c] + 32768u) >> 16);
        }
        same = same && dots.r == sum[0] && dots.g == sum[1] && dots.b == sum[2] && dots_half.r == sum[0] + 32768u &&
               dots_half.g == sum[1] + 32768u && dots_half.b == sum[2] + 32768u;
        if (!same) {
          ++mismatches;
          UNSCOPED_INFO("texels " << std::hex << t[0] << " " << t[1] << " " << t[2] << " " << t[3] << std::dec << ", fx "
                                  << fx << ", fy " << fy);
        }
      }
    }
  }
  INFO(compared << " blends compared");
  CHECK(compared == static_cast<long long>(sets.size()) * 65536);
  CHECK(mismatches == 0);
}

TEST_CASE("the samplers for a size fixed at compile time equal the general repeat samplers to the bit", "[sample]") {
  // BilinearRepeatOfSize / NearestRepeatOfSize (Features::repeat_sizes) restate
  // bilinear_repeat / nearest_repeat with the size as constants; the passes rely
  // on them giving the same bytes. Random 32-bit coordinates (every wrap).
  std::independent_bits_engine<std::mt19937, 32, std::uint32_t> random(0x5a3e1e);  // 32-bit results: the same sequence
  auto check_size = [&]<int WL, int HL>() {
    const int width = 1 << WL, height = 1 << HL;
    spanlight::scene::Image image{width, height, std::vector<std::uint8_t>(static_cast<std::size_t>(width * height * 3))};
    for (std::uint8_t& c : image.rgb) c = static_cast<std::uint8_t>(random());
    const std::vector<std::uint32_t> framed = spanlight::prepare::framed_texels(image, Wrap::repeat);
    const auto stride = static_cast<std::uint16_t>(width + 2);
    const spanlight::TextureLevel level{framed.data() + stride + 1, static_cast<std::uint16_t>(width),
                                        static_cast<std::uint16_t>(height), stride};
    const TexelGrid g = spanlight::texel_grid(level, 8);
    const spanlight::BilinearRepeatOfSize<WL, HL> bilinear{level.texels};
    const spanlight::NearestRepeatOfSize<WL, HL> nearest{level.texels};
    int wrong = 0;
    for (int n = 0; n < 4000; ++n) {
      const std::uint32_t x = random(), y = random();
      wrong += !(bilinear(x, y) == spanlight::bilinear_repeat(g, x, y));
      wrong += !(nearest(x, y) == spanlight::nearest_repeat(g, x, y));
    }
    INFO("size " << width << "x" << height);
    CHECK(wrong == 0);
  };
  check_size.template operator()<1, 2>();
  check_size.template operator()<4, 4>();
  check_size.template operator()<6, 3>();
  check_size.template operator()<8, 8>();
}

TEST_CASE("a repeating texture one texel wide or high is baked two wide or high and reads its own texels", "[sample]") {
  // A repeating 1xN texture is valid (a power of two), and every coordinate wraps to its one
  // column. The sampler's texel index is the top log2(width) bits of a 32-bit coordinate, and
  // log2 1 = 0 would shift by 32, so prepare bakes it doubled (repeatable_image): 2xN, the two
  // columns the same, which every coordinate reads as the 1xN texture.
  spanlight::scene::Image image{1, 4, {}};
  for (int row = 0; row < 4; ++row) {
    image.rgb.push_back(static_cast<std::uint8_t>(60 * row));
    image.rgb.push_back(7);
    image.rgb.push_back(9);
  }
  const spanlight::scene::Image baked = spanlight::prepare::repeatable_image(image);
  REQUIRE(baked.width == 2);
  REQUIRE(baked.height == 4);
  const std::vector<std::uint32_t> framed = spanlight::prepare::framed_texels(baked, Wrap::repeat);
  const spanlight::TextureLevel level{framed.data() + 4 + 1, 2, 4, 4};
  const TexelGrid g = spanlight::texel_grid(level, 8);
  REQUIRE(g.x_shift < 32);
  // v = 1.5 texels of 4 (a fraction 1.5 / 4 of 2^32): row_from_bottom 1 = row_from_top 2: r 120.
  const std::uint32_t v = 0x60000000u;
  int wrong = 0;
  for (const std::uint32_t u : {0u, 0x40000000u, 0x80000000u, 0xFFFFFFFFu}) {
    wrong += rgb(spanlight::nearest_repeat(g, u, v)) != std::array<int, 3>{120, 7, 9};
    // Bilinear half a texel back: v = 1.0 texel, fy = 0, both columns the one texel.
    wrong += rgb(spanlight::bilinear_repeat(g, u, 0x40000000u)) != std::array<int, 3>{120, 7, 9};
  }
  CHECK(wrong == 0);
}
