// Image comparison for spanlight: how far a picture is from the reference.
// The arithmetic is OpenImageIO's (ImageBufAlgo::compare, absdiff, maxchan,
// color_range_check, color_map); this module only fixes the definitions:
//
//   LSB             one 8-bit level (1/255). Images are compared as 8-bit RGB
//                   (io::read_rgb8_image: grey expanded, alpha dropped, at most
//                   4096 texels a side).
//   psnr_db         20 * log10(1 / rms), rms over all pixels and all three
//                   channels in [0, 1] units (peak 255 LSB). +inf when the images
//                   are identical: "inf" in text, null in JSON.
//   max_abs_lsb     the largest |a - b| of any channel of any pixel.
//   mean_abs_lsb    the mean of |a - b| over all pixels and all three channels.
//   pct_over_N_lsb  the percentage (0..100) of pixels whose largest channel
//                   difference exceeds N LSB (N = 2: >= 3 levels off somewhere).
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>

#include "io/image_file.hpp"

namespace spanlight::compare {

// An 8-bit RGB image in memory, top row first (what renderers produce).
struct Rgb8View {
  int width = 0;
  int height = 0;
  std::span<const std::uint8_t> rgb;  // width * height * 3
};

struct CompareResult {
  double psnr_db = 0.0;  // +inf for identical images
  double max_abs_lsb = 0.0;
  double mean_abs_lsb = 0.0;
  double pct_over_2_lsb = 0.0;
  double pct_over_8_lsb = 0.0;
  int width = 0;
  int height = 0;
};

// Unreadable file, buffer of the wrong length, or images of different sizes.
class CompareError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

CompareResult compare_images(const std::filesystem::path& a, const std::filesystem::path& b);
CompareResult compare_images(Rgb8View a, Rgb8View b);

// A picture of where the images differ: each pixel's largest channel |diff|,
// black for 0, then on a log scale blue (1 LSB), green (~3), yellow (~10),
// red (32 LSB and more), so a one-level difference already stands out.
// Throws CompareError for unreadable or mismatched inputs.
io::Rgb8Image heat_map(const std::filesystem::path& a, const std::filesystem::path& b);
io::Rgb8Image heat_map(Rgb8View a, Rgb8View b);

// The heat map's colour for a difference of `lsb` levels (>= 32 is red).
std::array<std::uint8_t, 3> heat_map_colour(int lsb);

// {"width": W, "height": H, "psnr_db": number or null (identical), "max_abs_lsb": ..,
//  "mean_abs_lsb": .., "pct_over_2_lsb": .., "pct_over_8_lsb": ..}
std::string to_json(const CompareResult& result);
// Several aligned "label  value" lines, one per figure.
std::string to_text(const CompareResult& result);
// All figures on one line, for logs.
std::string to_one_line(const CompareResult& result);
// A PSNR as the reports print it: two decimals, "inf" for identical images.
std::string psnr_text(double psnr_db);

// An 8-bit RGB image (top row first) encoded as PNG, in memory: the bytes a
// command hands to io::write_file_atomically. Throws CompareError.
std::string png_bytes(Rgb8View image);

// png_bytes() written with io::write_file_atomically (no inputs to protect:
// for tests and tools). On failure returns false and, when `error` is given, says why.
bool write_png_atomically(const std::filesystem::path& path, int width, int height,
                          std::span<const std::uint8_t> rgb8, std::string* error = nullptr);

}  // namespace spanlight::compare
