// Host FrameSink: the PPM file through stdio.
#include "hal/hal.hpp"
#include "ppm_layout.hpp"

#include <cstdio>

namespace spanlight::hal {
namespace {

std::FILE* file_of(std::intptr_t handle) { return reinterpret_cast<std::FILE*>(handle); }

}  // namespace

bool FrameSink::open(const char* path, FrameSize size) {
  if (!close()) {
    return false;
  }
  std::FILE* file = std::fopen(path, "wb");
  if (file == nullptr) {
    return false;
  }
  handle_ = reinterpret_cast<std::intptr_t>(file);
  size_ = size;
  const ppm::Header header = ppm::make_header(size);
  return std::fwrite(header.text.c_str(), 1, header.length, file) == header.length;
}

bool FrameSink::write_frame(std::span<const std::uint8_t> rgb) {
  if (handle_ == -1 || rgb.size() != frame_bytes(size_)) {
    return false;
  }
  const std::size_t header_length = ppm::make_header(size_).length;
  std::FILE* file = file_of(handle_);
  return std::fseek(file, static_cast<long>(header_length), SEEK_SET) == 0 &&
         std::fwrite(rgb.data(), 1, rgb.size(), file) == rgb.size();
}

bool FrameSink::flush_rect(Rect rect, std::span<const std::uint8_t> rgb, std::size_t stride_bytes) {
  if (handle_ == -1 || !ppm::rect_fits(rect, size_, rgb.size(), stride_bytes)) {
    return false;
  }
  const std::size_t header_length = ppm::make_header(size_).length;
  const std::size_t row_bytes = std::size_t{rect.width} * kBytesPerPixel;
  std::FILE* file = file_of(handle_);
  for (std::size_t row = 0; row < rect.height; ++row) {
    const std::size_t offset = ppm::pixel_offset(header_length, size_, rect.x, rect.y + row);
    if (std::fseek(file, static_cast<long>(offset), SEEK_SET) != 0 ||
        std::fwrite(rgb.data() + row * stride_bytes, 1, row_bytes, file) != row_bytes) {
      return false;
    }
  }
  return true;
}

bool FrameSink::close() {
  if (handle_ == -1) {
    return true;
  }
  std::FILE* file = file_of(handle_);
  handle_ = -1;
  return std::fclose(file) == 0;
}

}  // namespace spanlight::hal
