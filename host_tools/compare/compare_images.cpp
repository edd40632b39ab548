#include <cmath>
#include <limits>

#include <OpenImageIO/imagebufalgo.h>

#include "compare/compare.hpp"
#include "compare/difference.hpp"
#include "compare/rgb_image.hpp"

namespace spanlight::compare {

namespace {

constexpr double lsb = 1.0 / 255.0;

// Percentage of pixels whose largest channel difference exceeds `levels` LSB.
// The threshold sits half a level above, so float round-off in OIIO's [0, 1]
// arithmetic cannot move a whole-level difference across it.
double percent_over(const OIIO::ImageBuf& max_difference, int levels) {
  OIIO::imagesize_t over = 0;
  const float low = -1.0f;
  const float high = static_cast<float>((levels + 0.5) * lsb);
  if (!OIIO::ImageBufAlgo::color_range_check(max_difference, nullptr, &over, nullptr, low, high)) {
    throw CompareError("color_range_check: " + max_difference.geterror());
  }
  const auto pixels = max_difference.spec().image_pixels();
  return 100.0 * static_cast<double>(over) / static_cast<double>(pixels);
}

// OIIO works in float [0, 1]: |k/255.0f - m/255.0f| * 255 is k - m only to ~3e-5.
// Rounding to 1/1000 LSB gives whole levels back as whole numbers.
double without_float_noise(double value_in_lsb) { return std::round(value_in_lsb * 1000.0) / 1000.0; }

CompareResult compare_buffers(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b) {
  require_same_size(a, b);
  // Thresholds are unused here: the percentages come from the max-channel image.
  const OIIO::ImageBufAlgo::CompareResults stats = OIIO::ImageBufAlgo::compare(a, b, 1.0f, 1.0f);
  if (stats.error) throw CompareError("compare: " + a.geterror() + b.geterror());

  const OIIO::ImageBuf max_difference = max_channel_difference(a, b);
  CompareResult result;
  result.width = a.spec().width;
  result.height = a.spec().height;
  result.psnr_db = stats.rms_error > 0.0 ? 20.0 * std::log10(1.0 / stats.rms_error)
                                         : std::numeric_limits<double>::infinity();
  result.max_abs_lsb = without_float_noise(stats.maxerror / lsb);
  result.mean_abs_lsb = without_float_noise(stats.meanerror / lsb);
  result.pct_over_2_lsb = percent_over(max_difference, 2);
  result.pct_over_8_lsb = percent_over(max_difference, 8);
  return result;
}

}  // namespace

CompareResult compare_images(const std::filesystem::path& a, const std::filesystem::path& b) {
  const ImagePair images = read_same_size(a, b);
  return compare_buffers(images.a, images.b);
}

CompareResult compare_images(Rgb8View a, Rgb8View b) { return compare_buffers(to_image_buf(a), to_image_buf(b)); }

}  // namespace spanlight::compare
