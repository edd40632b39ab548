// Reading an image file as 8-bit RGB, for scene textures and `spanlight compare`
// alike: the file is read whole through read_regular_file, its header checked
// before a pixel is decoded, then OpenImageIO decodes it from memory.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>
#include <vector>

#include "io/read_file.hpp"

namespace spanlight::io {

// The scene format's image limit (1..4096 texels a side), also what `compare`
// reads: the largest picture any scene renders.
inline constexpr int max_image_side = 4096;
// A 4096 x 4096 RGBA image of 32-bit floats stored uncompressed is 256 MiB; no
// file of an image within the side limit needs more.
inline constexpr std::uintmax_t max_image_file_bytes = 256 * mebibyte;

struct Rgb8Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3, top row first
};

// Grey (one channel, or two: grey and alpha) is expanded to RGB; alpha is
// dropped, keeping the stored RGB (not multiplied by alpha); deeper formats
// (16-bit, float) are rounded to the nearest 8-bit level. Throws ReadError
// ("expected ..., got ...") for a file that is not a readable image of 1..4096
// texels a side with 1 to 4 channels; `kind` names it ("image file").
Rgb8Image read_rgb8_image(const std::filesystem::path& file, std::string_view kind);

}  // namespace spanlight::io
