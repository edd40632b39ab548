// Internal: getting both kinds of input into OpenImageIO as 3-channel images.
#pragma once

#include <filesystem>

#include <OpenImageIO/imagebuf.h>

#include "compare/compare.hpp"

namespace spanlight::compare {

// Reads a file as RGB through io::read_rgb8_image (grey expanded, alpha dropped,
// at most 4096 texels a side, header checked first). Throws CompareError naming the file.
OIIO::ImageBuf read_rgb(const std::filesystem::path& file);

// Throws CompareError unless view.rgb holds width * height RGB pixels.
void require_rgb8_size(Rgb8View view);

// Copies an in-memory RGB8 image into an ImageBuf. Throws CompareError on a bad length.
OIIO::ImageBuf to_image_buf(Rgb8View view);

// The 8-bit RGB pixels of an image, top row first.
io::Rgb8Image to_rgb8(const OIIO::ImageBuf& image);

// Throws CompareError unless both images have the same size.
void require_same_size(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b);

// Two files to set side by side, read as read_rgb reads them.
struct ImagePair {
  OIIO::ImageBuf a, b;
};

// Reads a, then b (an error names the first bad file); throws CompareError naming
// both files when their sizes differ.
ImagePair read_same_size(const std::filesystem::path& a, const std::filesystem::path& b);

}  // namespace spanlight::compare
