// The mipmap chain (scene/mip_chain.hpp): levels computed by hand, non-square chains,
// and the chain's size.
#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include <catch2/catch.hpp>

#include "scene/mip_chain.hpp"

using namespace spanlight::scene;

namespace {

// A grey image (r = g = b) from rows written top row first.
Image grey(int width, int height, const std::vector<int>& values) {
  Image image{width, height, {}};
  for (const int v : values) image.rgb.insert(image.rgb.end(), 3, static_cast<std::uint8_t>(v));
  REQUIRE(image.rgb.size() == static_cast<std::size_t>(width * height * 3));
  return image;
}

std::vector<int> grey_values(const Image& image) {
  std::vector<int> values;
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    CHECK(image.rgb[i] == image.rgb[i + 1]);
    CHECK(image.rgb[i] == image.rgb[i + 2]);
    values.push_back(image.rgb[i]);
  }
  return values;
}

}  // namespace

TEST_CASE("mip levels: each texel the mean of the 2x2 it covers, rounded half up", "[scene][mip]") {
  // Four 2x2 blocks with sums 2 (mean 0.5 -> 1), 1 (0.25 -> 0), 3 (0.75 -> 1) and
  // 510 (127.5 -> 128), then the 1x1 level: (1 + 0 + 1 + 128) / 4 = 32.5 -> 33.
  const Image image = grey(4, 4, {0, 1, 0, 0,  //
                                  1, 0, 1, 0,  //
                                  1, 1, 0, 255,
                                  0, 1, 255, 0});
  const std::vector<Image> chain = mip_chain(image);
  REQUIRE(chain.size() == 3);
  CHECK(chain[0].rgb == image.rgb);
  CHECK(chain[1].width == 2);
  CHECK(chain[1].height == 2);
  CHECK(grey_values(chain[1]) == std::vector<int>{1, 0, 1, 128});
  CHECK(chain[2].width == 1);
  CHECK(chain[2].height == 1);
  CHECK(grey_values(chain[2]) == std::vector<int>{33});
}

TEST_CASE("mip levels: channels are averaged on their own", "[scene][mip]") {
  Image image{2, 2, {}};
  const std::array<std::array<std::uint8_t, 3>, 4> texels = {{{255, 0, 10}, {255, 0, 11}, {0, 1, 10}, {0, 0, 11}}};
  for (const auto& texel : texels) image.rgb.insert(image.rgb.end(), texel.begin(), texel.end());
  const Image top = mip_chain(image).back();
  // 510 / 4 = 127.5 -> 128; 1 / 4 -> 0; 42 / 4 = 10.5 -> 11.
  CHECK(top.rgb == std::vector<std::uint8_t>{128, 0, 11});
}

TEST_CASE("non-square chains halve only the sides larger than 1", "[scene][mip]") {
  // 8x2 -> 4x1 (2x2 blocks) -> 2x1 (2x1 pairs) -> 1x1.
  const Image image = grey(8, 2, {0, 2, 4, 6, 8, 10, 12, 14,  //
                                  1, 3, 5, 7, 9, 11, 13, 15});
  const std::vector<Image> chain = mip_chain(image);
  REQUIRE(chain.size() == 4);
  CHECK(grey_values(chain[1]) == std::vector<int>{2, 6, 10, 14});  // (0+2+1+3)/4 = 1.5 -> 2, ...
  CHECK(chain[1].height == 1);
  CHECK(grey_values(chain[2]) == std::vector<int>{4, 12});  // (2+6)/2, (10+14)/2
  CHECK(grey_values(chain[3]) == std::vector<int>{8});

  // A column: 1x4 -> 1x2 -> 1x1, pairs (a + b + 1) / 2.
  const std::vector<Image> column = mip_chain(grey(1, 4, {0, 1, 200, 255}));
  REQUIRE(column.size() == 3);
  CHECK(grey_values(column[1]) == std::vector<int>{1, 228});  // 0.5 -> 1, 227.5 -> 228
  CHECK(grey_values(column[2]) == std::vector<int>{115});     // 114.5 -> 115
}

TEST_CASE("a one-texel checker's levels above 0 are all 128", "[scene][mip]") {
  std::vector<int> values;
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) values.push_back(((x + y) % 2) * 255);
  const std::vector<Image> chain = mip_chain(grey(16, 16, values));
  REQUIRE(chain.size() == 5);
  for (std::size_t level = 1; level < chain.size(); ++level) {
    for (const int v : grey_values(chain[level])) CHECK(v == 128);  // 510 / 4 = 127.5 -> 128, then 128 stays
  }
}

TEST_CASE("the chain's size: under 4/3 of a square image, under twice a thin one", "[scene][mip]") {
  for (int k = 0; k <= 12; ++k) {
    const int side = 1 << k;
    const std::size_t image = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
    INFO("side " << side);
    // Square: 4^k + 4^(k-1) + ... + 1 = (4^(k+1) - 1) / 3 < 4/3 * 4^k.
    CHECK(mip_chain_texels(side, side) == (4 * image - 1) / 3);
    CHECK(3 * mip_chain_texels(side, side) < 4 * image);
    // 2^k x 1: 2^k + 2^(k-1) + ... + 1 = 2 * 2^k - 1, beyond 4/3 for k >= 2: the spec's
    // "at most 4/3 of the image" holds for square images only.
    CHECK(mip_chain_texels(side, 1) == 2 * static_cast<std::size_t>(side) - 1);
    CHECK(mip_chain_texels(1, side) == 2 * static_cast<std::size_t>(side) - 1);
    // Any 2^a x 2^b: under twice the image.
    for (int b = 0; b <= k; ++b) CHECK(mip_chain_texels(side, 1 << b) < 2 * static_cast<std::size_t>(side) * (1u << b));
  }
  // mip_chain_texels counts what mip_chain builds.
  const std::vector<Image> chain = mip_chain(grey(8, 2, std::vector<int>(16, 7)));
  std::size_t built = 0;
  for (const Image& level : chain) built += static_cast<std::size_t>(level.width * level.height);
  CHECK(built == mip_chain_texels(8, 2));
}

TEST_CASE("a side that is not a power of two has no chain", "[scene][mip]") {
  CHECK_THROWS_AS(mip_chain(grey(3, 4, std::vector<int>(12, 0))), std::invalid_argument);
  CHECK_THROWS_AS(mip_chain(grey(4, 6, std::vector<int>(24, 0))), std::invalid_argument);
  CHECK_THROWS_AS(mip_chain_texels(4, 3), std::invalid_argument);
}
