// Byte layout of the binary PPM (P6) files FrameSink writes, shared by both HAL
// implementations so host and Cortex-M produce byte-identical files.
#pragma once

#include "hal/hal.hpp"
#include "hal/log_line.hpp"

#include <cstddef>

namespace spanlight::hal::ppm {

// "P6\n<width> <height>\n255\n": the header every PPM reader accepts, no comments.
struct Header {
  LogLine<32> text;
  std::size_t length = 0;
};

inline Header make_header(FrameSize size) {
  Header header;
  header.text << "P6\n" << size.width << " " << size.height << "\n255\n";
  for (const char* c = header.text.c_str(); *c != '\0'; ++c) {
    ++header.length;
  }
  return header;
}

// File offset of pixel (x, y).
inline std::size_t pixel_offset(std::size_t header_length, FrameSize size, std::size_t x, std::size_t y) {
  return header_length + (y * size.width + x) * kBytesPerPixel;
}

// The rectangle lies inside the frame, and rgb holds all of its rows at the given stride.
inline bool rect_fits(Rect rect, FrameSize size, std::size_t rgb_bytes, std::size_t stride_bytes) {
  if (rect.width == 0 || rect.height == 0) {
    return false;
  }
  const std::size_t row_bytes = std::size_t{rect.width} * kBytesPerPixel;
  return std::size_t{rect.x} + rect.width <= size.width && std::size_t{rect.y} + rect.height <= size.height &&
         stride_bytes >= row_bytes && (std::size_t{rect.height} - 1) * stride_bytes + row_bytes <= rgb_bytes;
}

}  // namespace spanlight::hal::ppm
