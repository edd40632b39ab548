#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <OpenImageIO/imagebufalgo.h>

#include "compare/compare.hpp"
#include "compare/difference.hpp"
#include "compare/rgb_image.hpp"

namespace spanlight::compare {

namespace {

constexpr int red_at_lsb = 32;  // differences of 32 levels and more are all red

using Rgb = std::array<double, 3>;

// Blue, green, yellow, red at equal steps of log2(lsb) from 1 to 32: each doubling
// of the error moves the colour by the same amount, so 1 and 2 LSB look different.
Rgb ramp(int lsb) {
  if (lsb <= 0) return {0.0, 0.0, 0.0};
  static constexpr std::array<Rgb, 4> stops{{{0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}};
  const double position = std::log2(std::min(lsb, red_at_lsb)) / std::log2(red_at_lsb) * 3.0;  // 0..3
  const auto segment = std::min(static_cast<std::size_t>(position), std::size_t{2});
  const double f = position - static_cast<double>(segment);
  Rgb colour{};
  for (std::size_t c = 0; c < 3; ++c) colour[c] = stops[segment][c] * (1.0 - f) + stops[segment + 1][c] * f;
  return colour;
}

io::Rgb8Image heat_map_of(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b) {
  require_same_size(a, b);
  // One knot per whole level 0..32; OIIO's color_map spaces knots evenly over [0, 1].
  std::vector<float> knots;
  for (int lsb = 0; lsb <= red_at_lsb; ++lsb) {
    for (std::uint8_t channel : heat_map_colour(lsb)) knots.push_back(static_cast<float>(channel) / 255.0f);
  }
  const OIIO::ImageBuf difference = max_channel_difference(a, b);  // [0, 1] units
  const float to_knot_units = 255.0f / static_cast<float>(red_at_lsb);
  const OIIO::ImageBuf position = OIIO::ImageBufAlgo::clamp(OIIO::ImageBufAlgo::mul(difference, to_knot_units), 0.0f, 1.0f);
  const OIIO::ImageBuf heat = OIIO::ImageBufAlgo::color_map(position, 0, red_at_lsb + 1, 3, knots);
  if (heat.has_error()) throw CompareError("heat map: " + heat.geterror());
  return to_rgb8(heat);
}

}  // namespace

std::array<std::uint8_t, 3> heat_map_colour(int lsb) {
  const Rgb colour = ramp(lsb);
  std::array<std::uint8_t, 3> out{};
  for (std::size_t c = 0; c < 3; ++c) out[c] = static_cast<std::uint8_t>(std::lround(colour[c] * 255.0));
  return out;
}

io::Rgb8Image heat_map(const std::filesystem::path& a, const std::filesystem::path& b) {
  const ImagePair images = read_same_size(a, b);
  return heat_map_of(images.a, images.b);
}

io::Rgb8Image heat_map(Rgb8View a, Rgb8View b) { return heat_map_of(to_image_buf(a), to_image_buf(b)); }

}  // namespace spanlight::compare
