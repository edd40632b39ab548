// Shared by the demo apps: pixels out of the colour buffer and into the HAL's FrameSink
// as RGB888 rows, one row buffer at a time, the way a display driver takes spans.
//   write_rows(...)   rows of a buffer (the whole frame, or one band)
//   BandSink          render_frame's hooks: each finished band goes out as it is done
// (Hooks::band_done). BandSink stops the app's CostCounter while it pushes, so a measured
// region holds only rendering: a frame in B bands is B + 1 regions.
#pragma once

#include <cstdint>
#include <span>

#include "hal/hal.hpp"
#include "spanlight/hooks.hpp"
#include "spanlight/4_pixel/colour.hpp"

namespace spanlight::apps {

// Rows [0, rows) of `colour` (width pixels a row) to the sink's rows first_row.., through `line`
// (width * 3 bytes). A null sink writes nothing.
template <PixelFormat Format>
bool write_rows(hal::FrameSink* sink, std::uint16_t width, std::uint16_t first_row, std::uint16_t rows,
                const typename ColorTraits<Format>::Storage* colour, std::span<std::uint8_t> line) {
  using Color = ColorTraits<Format>;
  if (sink == nullptr) return true;
  for (std::uint16_t y = 0; y < rows; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const Colour c = Color::load(colour + (std::uint32_t{y} * width + x) * Color::per_pixel);
      line[x * 3] = static_cast<std::uint8_t>(red(c));
      line[x * 3 + 1] = static_cast<std::uint8_t>(green(c));
      line[x * 3 + 2] = static_cast<std::uint8_t>(blue(c));
    }
    if (!sink->flush_rect({0, static_cast<std::uint16_t>(first_row + y), width, 1}, line, line.size())) return false;
  }
  return true;
}

template <PixelFormat Format>
struct BandSink : NoHooks {
  hal::FrameSink* sink;         // null: render only
  std::span<std::uint8_t> line; // width * 3 bytes
  std::uint16_t width;
  hal::CostCounter* cost;       // paused while a band is pushed; may be null
  bool ok = true;

  template <typename Storage>
  void band_done(std::uint16_t first_row, std::uint16_t rows, const Storage* colour) {
    if (cost != nullptr) cost->end();
    ok = write_rows<Format>(sink, width, first_row, rows, colour, line) && ok;
    if (cost != nullptr) cost->begin();
  }
};

}  // namespace spanlight::apps
