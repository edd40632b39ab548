// The compare module: figures on images whose differences are known, the heat
// map's colours, and PNG output that never leaves a half-written file.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <OpenImageIO/imagebuf.h>

#include "compare/compare.hpp"
#include "test_scenes.hpp"

namespace cmp = spanlight::compare;

namespace {

constexpr int width = 20;
constexpr int height = 10;

// A gradient with levels 0..254 only, so +1 never overflows. Red and green are
// small in the first pixels, where the tests add more.
std::vector<std::uint8_t> gradient() {
  std::vector<std::uint8_t> rgb;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const int i = y * width + x;
      rgb.insert(rgb.end(), {static_cast<std::uint8_t>(i % 255), static_cast<std::uint8_t>((i * 7) % 255),
                             static_cast<std::uint8_t>(254 - i % 255)});
    }
  }
  return rgb;
}

cmp::Rgb8View view(const std::vector<std::uint8_t>& rgb) { return {width, height, rgb}; }

std::vector<std::uint8_t> read_png(const std::filesystem::path& file) {
  OIIO::ImageBuf image(file.string());
  REQUIRE(image.read(0, 0, true, OIIO::TypeDesc::UINT8));
  REQUIRE(image.nchannels() == 3);
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(image.spec().width * image.spec().height * 3));
  image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, rgb.data());
  return rgb;
}

}  // namespace

TEST_CASE("identical images: no error and infinite PSNR, printed as inf and null", "[compare]") {
  const auto a = gradient();
  const cmp::CompareResult r = cmp::compare_images(view(a), view(a));
  CHECK(std::isinf(r.psnr_db));
  CHECK(r.psnr_db > 0);
  CHECK(r.max_abs_lsb == 0.0);
  CHECK(r.mean_abs_lsb == 0.0);
  CHECK(r.pct_over_2_lsb == 0.0);
  CHECK(r.pct_over_8_lsb == 0.0);
  CHECK(r.width == width);
  CHECK(r.height == height);
  CHECK(cmp::to_text(r).find("inf dB") != std::string::npos);
  CHECK(cmp::to_one_line(r).find("PSNR inf dB") != std::string::npos);
  CHECK(cmp::to_json(r).find("\"psnr_db\": null") != std::string::npos);
}

TEST_CASE("every channel one level up: max and mean 1 LSB, PSNR 20 log10(255), nothing over 2 LSB", "[compare]") {
  const auto a = gradient();
  auto b = a;
  for (auto& v : b) ++v;
  const cmp::CompareResult r = cmp::compare_images(view(a), view(b));
  CHECK(r.max_abs_lsb == 1.0);
  CHECK(r.mean_abs_lsb == 1.0);
  CHECK(r.psnr_db == Approx(20.0 * std::log10(255.0)).epsilon(1e-6));
  CHECK(r.pct_over_2_lsb == 0.0);
  CHECK(r.pct_over_8_lsb == 0.0);
  CHECK(cmp::to_json(r).find("\"max_abs_lsb\": 1.0") != std::string::npos);
}

TEST_CASE("the percentages count pixels by their largest channel difference, strictly over the limit", "[compare]") {
  const auto a = gradient();
  auto b = a;
  const auto bump = [&](int pixel, int channel, int levels) { b[static_cast<std::size_t>(pixel * 3 + channel)] += static_cast<std::uint8_t>(levels); };
  bump(0, 0, 2);   // exactly 2: not over 2
  bump(1, 1, 3);   // over 2
  bump(2, 0, 8);   // over 2, not over 8
  bump(3, 0, 9);   // over both
  bump(3, 1, 9);   // same pixel again: still one pixel
  bump(4, 1, 40);  // over both
  const cmp::CompareResult r = cmp::compare_images(view(a), view(b));
  const double pixels = width * height;
  CHECK(r.pct_over_2_lsb == Approx(100.0 * 4 / pixels));
  CHECK(r.pct_over_8_lsb == Approx(100.0 * 2 / pixels));
  CHECK(r.max_abs_lsb == 40.0);
  CHECK(r.mean_abs_lsb == Approx((2.0 + 3 + 8 + 9 + 9 + 40) / (pixels * 3)).margin(1e-3));
}

TEST_CASE("files compare like the buffers they hold, and mismatched sizes are an error", "[compare]") {
  const auto folder = spanlight::test::fresh_folder("compare_files");
  const auto a = gradient();
  auto b = a;
  b[3] += 6;  // pixel 1, red
  REQUIRE(cmp::write_png_atomically(folder / "a.png", width, height, a));
  REQUIRE(cmp::write_png_atomically(folder / "b.png", width, height, b));
  const cmp::CompareResult from_files = cmp::compare_images(folder / "a.png", folder / "b.png");
  const cmp::CompareResult from_buffers = cmp::compare_images(view(a), view(b));
  CHECK(from_files.max_abs_lsb == 6.0);
  CHECK(from_files.psnr_db == Approx(from_buffers.psnr_db));
  CHECK(from_files.pct_over_2_lsb == Approx(from_buffers.pct_over_2_lsb));

  const std::vector<std::uint8_t> small(10 * 5 * 3, 0);
  CHECK_THROWS_AS(cmp::compare_images(view(a), cmp::Rgb8View{10, 5, small}), cmp::CompareError);
  CHECK_THROWS_AS(cmp::compare_images(view(a), cmp::Rgb8View{width, height, small}), cmp::CompareError);
  CHECK_THROWS_AS(cmp::compare_images(folder / "a.png", folder / "missing.png"), cmp::CompareError);
  std::filesystem::remove_all(folder);
}

TEST_CASE("the heat map is black where equal, blue at 1 LSB and red from 32 LSB", "[compare]") {
  CHECK(cmp::heat_map_colour(0) == std::array<std::uint8_t, 3>{0, 0, 0});
  CHECK(cmp::heat_map_colour(1) == std::array<std::uint8_t, 3>{0, 0, 255});
  CHECK(cmp::heat_map_colour(32) == std::array<std::uint8_t, 3>{255, 0, 0});
  CHECK(cmp::heat_map_colour(200) == std::array<std::uint8_t, 3>{255, 0, 0});
  CHECK(cmp::heat_map_colour(2) != cmp::heat_map_colour(1));  // small differences stay distinguishable

  const auto folder = spanlight::test::fresh_folder("heat_map");
  const auto a = gradient();
  auto b = a;
  b[0 * 3 + 1] += 1;   // pixel 0: 1 LSB in green
  b[1 * 3 + 0] += 5;   // pixel 1: 5 LSB
  b[2 * 3 + 0] = static_cast<std::uint8_t>(a[6] >= 128 ? 0 : 255);  // pixel 2: far over 32
  const spanlight::io::Rgb8Image heat_image = cmp::heat_map(view(a), view(b));
  REQUIRE(cmp::write_png_atomically(folder / "heat.png", heat_image.width, heat_image.height, heat_image.rgb));
  const auto heat = read_png(folder / "heat.png");
  const auto colour_at = [&](int pixel) {
    return std::array<std::uint8_t, 3>{heat[static_cast<std::size_t>(pixel * 3)], heat[static_cast<std::size_t>(pixel * 3 + 1)],
                                       heat[static_cast<std::size_t>(pixel * 3 + 2)]};
  };
  CHECK(colour_at(0) == cmp::heat_map_colour(1));
  CHECK(colour_at(1) == cmp::heat_map_colour(5));
  CHECK(colour_at(2) == cmp::heat_map_colour(32));
  CHECK(colour_at(3) == cmp::heat_map_colour(0));

  // From files, the same picture.
  REQUIRE(cmp::write_png_atomically(folder / "a.png", width, height, a));
  REQUIRE(cmp::write_png_atomically(folder / "b.png", width, height, b));
  CHECK(cmp::heat_map(folder / "a.png", folder / "b.png").rgb == heat);
  std::filesystem::remove_all(folder);
}

TEST_CASE("write_png_atomically writes the picture, leaves no temporary behind, and nothing on failure", "[compare]") {
  const auto folder = spanlight::test::fresh_folder("png");
  const auto a = gradient();
  SECTION("success: the file holds the pixels and is the folder's only entry") {
    REQUIRE(cmp::write_png_atomically(folder / "out.png", width, height, a));
    CHECK(read_png(folder / "out.png") == a);
    // Overwriting an existing file works the same way.
    auto b = a;
    b[0] = 77;
    REQUIRE(cmp::write_png_atomically(folder / "out.png", width, height, b));
    CHECK(read_png(folder / "out.png") == b);
    int entries = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++entries;
    CHECK(entries == 1);
  }
  SECTION("a folder that does not exist: false, a reason, and no file") {
    std::string error;
    const auto missing = folder / "no_such_folder" / "out.png";
    CHECK_FALSE(cmp::write_png_atomically(missing, width, height, a, &error));
    CHECK(!error.empty());
    CHECK_FALSE(std::filesystem::exists(missing));
    CHECK_FALSE(std::filesystem::exists(folder / "no_such_folder"));
    CHECK(std::filesystem::is_empty(folder));
  }
  SECTION("a buffer of the wrong length: false and no file") {
    CHECK_FALSE(cmp::write_png_atomically(folder / "short.png", width, height, std::span(a).first(10)));
    CHECK(std::filesystem::is_empty(folder));
  }
  std::filesystem::remove_all(folder);
}
