// Cortex-M FrameSink: the PPM file is opened on the host through semihosting (relative paths
// resolve against QEMU's working directory). Each row or frame is one SYS_WRITE straight
// from the caller's buffer.
#include "hal/hal.hpp"
#include "ppm_layout.hpp"
#include "startup/semihosting.h"

namespace spanlight::hal {
namespace {

int semihost_handle(std::intptr_t handle) { return static_cast<int>(handle); }

bool write_at(int handle, std::size_t offset, const std::uint8_t* data, std::size_t length) {
  return spanlight_semihost_seek(handle, offset) == 0 && spanlight_semihost_write(handle, data, length) == 0;
}

}  // namespace

bool FrameSink::open(const char* path, FrameSize size) {
  if (!close()) {
    return false;
  }
  const int handle = spanlight_semihost_open(path, SPANLIGHT_SEMIHOST_MODE_WRITE_BINARY);
  if (handle == -1) {
    return false;
  }
  handle_ = handle;
  size_ = size;
  const ppm::Header header = ppm::make_header(size);
  return spanlight_semihost_write(handle, header.text.c_str(), header.length) == 0;
}

bool FrameSink::write_frame(std::span<const std::uint8_t> rgb) {
  if (handle_ == -1 || rgb.size() != frame_bytes(size_)) {
    return false;
  }
  return write_at(semihost_handle(handle_), ppm::make_header(size_).length, rgb.data(), rgb.size());
}

bool FrameSink::flush_rect(Rect rect, std::span<const std::uint8_t> rgb, std::size_t stride_bytes) {
  if (handle_ == -1 || !ppm::rect_fits(rect, size_, rgb.size(), stride_bytes)) {
    return false;
  }
  const std::size_t header_length = ppm::make_header(size_).length;
  const std::size_t row_bytes = std::size_t{rect.width} * kBytesPerPixel;
  for (std::size_t row = 0; row < rect.height; ++row) {
    const std::size_t offset = ppm::pixel_offset(header_length, size_, rect.x, rect.y + row);
    if (!write_at(semihost_handle(handle_), offset, rgb.data() + row * stride_bytes, row_bytes)) {
      return false;
    }
  }
  return true;
}

bool FrameSink::close() {
  if (handle_ == -1) {
    return true;
  }
  const int handle = semihost_handle(handle_);
  handle_ = -1;
  return spanlight_semihost_close(handle) == 0;
}

}  // namespace spanlight::hal
