// Images become 8-bit RGB, top row first: grey is expanded, alpha dropped
// (not multiplied in), deeper formats rounded to 8 bits.
#include <cstdint>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <catch2/catch.hpp>

#include "scene/scene.hpp"
#include "scratch_folder.hpp"

using namespace spanlight::scene;
using spanlight::scene::test::ScratchFolder;

namespace {

using Rgb = std::array<std::uint8_t, 3>;

// Writes pixels (top row first, channels interleaved) as they are: with
// UnassociatedAlpha OIIO does not divide RGB by alpha on the way out.
template <typename Channel>
void write_png(const std::filesystem::path& file, int width, int height, int channels,
               const std::vector<Channel>& pixels, OIIO::TypeDesc format) {
  OIIO::ImageSpec spec(width, height, channels, format);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  auto out = OIIO::ImageOutput::create(file.string());
  REQUIRE(out);
  REQUIRE(out->open(file.string(), spec));
  REQUIRE(out->write_image(format, pixels.data()));
  REQUIRE(out->close());
}

// Loads image.png through a one-texture scene, the only way in.
Image load_texture_image(const ScratchFolder& folder) {
  const auto scene_file = folder.write("scene.json", R"({
    "spanlight_scene": 1, "output": { "width": 8, "height": 8 },
    "camera": { "eye": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fovy_deg": 60, "near": 0.1, "far": 10 },
    "textures": { "t": { "image": "image.png", "wrap": "clamp" } } })");
  return load_scene(scene_file).textures.at(0).image;
}

}  // namespace

TEST_CASE("the first row of the file is row 0 of the Image", "[scene][image]") {
  const ScratchFolder folder;
  // 1 wide, 2 high: red on top, blue below.
  write_png<std::uint8_t>(folder.path() / "image.png", 1, 2, 3, {255, 0, 0, 0, 0, 255}, OIIO::TypeDesc::UINT8);
  const Image image = load_texture_image(folder);
  REQUIRE(image.width == 1);
  REQUIRE(image.height == 2);
  CHECK(image.texel(0, 0) == Rgb{255, 0, 0});
  CHECK(image.texel(0, 1) == Rgb{0, 0, 255});
}

TEST_CASE("a grey image is expanded to RGB", "[scene][image]") {
  const ScratchFolder folder;
  write_png<std::uint8_t>(folder.path() / "image.png", 3, 1, 1, {0, 77, 255}, OIIO::TypeDesc::UINT8);
  const Image image = load_texture_image(folder);
  REQUIRE(image.rgb.size() == 9);
  CHECK(image.texel(1, 0) == Rgb{77, 77, 77});
  CHECK(image.texel(2, 0) == Rgb{255, 255, 255});
}

TEST_CASE("grey with alpha is grey, alpha ignored", "[scene][image]") {
  const ScratchFolder folder;
  write_png<std::uint8_t>(folder.path() / "image.png", 2, 1, 2, {90, 0, 200, 128}, OIIO::TypeDesc::UINT8);
  const Image image = load_texture_image(folder);
  CHECK(image.texel(0, 0) == Rgb{90, 90, 90});
  CHECK(image.texel(1, 0) == Rgb{200, 200, 200});
}

TEST_CASE("RGBA keeps its stored RGB whatever the alpha", "[scene][image]") {
  const ScratchFolder folder;
  write_png<std::uint8_t>(folder.path() / "image.png", 2, 1, 4, {200, 100, 50, 0, 10, 20, 30, 128},
                          OIIO::TypeDesc::UINT8);
  const Image image = load_texture_image(folder);
  REQUIRE(image.rgb.size() == 6);
  CHECK(image.texel(0, 0) == Rgb{200, 100, 50});  // alpha 0 must not blacken it
  CHECK(image.texel(1, 0) == Rgb{10, 20, 30});
}

TEST_CASE("a 16-bit image is rounded to 8 bits", "[scene][image]") {
  const ScratchFolder folder;
  // 32896 / 65535 = 128 / 255 exactly; 65535 is full scale.
  write_png<std::uint16_t>(folder.path() / "image.png", 1, 1, 3, {0, 32896, 65535}, OIIO::TypeDesc::UINT16);
  CHECK(load_texture_image(folder).texel(0, 0) == Rgb{0, 128, 255});
}

TEST_CASE("16-bit channels round to the nearest 8-bit level, v * 255 / 65535", "[scene][image]") {
  // The spec names channels (grey, RGB, RGBA), not depths; the pipeline's texels are
  // 8-bit, so deeper files are rounded, the same rule as output files: round(255 * value).
  const ScratchFolder folder;
  // 128 and 129 straddle 0.5 levels (0.498, 0.502); 32767 and 32768 straddle 127.5.
  write_png<std::uint16_t>(folder.path() / "image.png", 2, 1, 3, {128, 129, 32767, 32768, 65534, 1},
                           OIIO::TypeDesc::UINT16);
  const Image image = load_texture_image(folder);
  CHECK(image.texel(0, 0) == Rgb{0, 1, 127});
  CHECK(image.texel(1, 0) == Rgb{128, 255, 0});
}
