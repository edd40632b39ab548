// selftest: exercises every HAL service the real apps use, on host and target alike.
//   0. checks the start-up state (.data, .bss, constructors);
//   1. fills a static 320x240 RGB888 frame with the test pattern inside a measured region;
//   2. writes it whole (FrameSink::write_frame) to args[1];
//   3. writes it again as 32x16 tiles, in column order, (FrameSink::flush_rect) to args[2];
//   4. logs the cost, a checksum and the stack high-water mark, and returns 0.
// The tests compare both files with the host build's output byte for byte.
#include "hal/hal.hpp"
#include "hal/log_line.hpp"
#include "startup_probe.hpp"
#include "test_pattern.hpp"

#include <array>
#include <cstdint>

namespace {

using namespace spanlight;

constexpr hal::FrameSize kFrameSize{320, 240};
constexpr std::uint16_t kTileWidth = 32;
constexpr std::uint16_t kTileHeight = 16;

// Static: 230 KB is far too much for the stack, and there is no heap.
std::array<std::uint8_t, hal::frame_bytes(kFrameSize)> framebuffer;

const char* argument_or(hal::Args args, std::size_t index, const char* fallback) {
  return args.size() > index ? args[index] : fallback;
}

bool write_whole(const char* path) {
  hal::FrameSink sink;
  return sink.open(path, kFrameSize) && sink.write_frame(framebuffer) && sink.close();
}

// Column-major order on purpose: tiles arrive out of file order, as from a tiled renderer.
bool write_tiles(const char* path) {
  hal::FrameSink sink;
  if (!sink.open(path, kFrameSize)) {
    return false;
  }
  constexpr std::size_t kStride = std::size_t{kFrameSize.width} * hal::kBytesPerPixel;
  for (std::uint16_t x = 0; x < kFrameSize.width; x = static_cast<std::uint16_t>(x + kTileWidth)) {
    for (std::uint16_t y = 0; y < kFrameSize.height; y = static_cast<std::uint16_t>(y + kTileHeight)) {
      const std::size_t first = y * kStride + std::size_t{x} * hal::kBytesPerPixel;
      const hal::Rect tile{x, y, kTileWidth, kTileHeight};
      if (!sink.flush_rect(tile, std::span(framebuffer).subspan(first), kStride)) {
        return false;
      }
    }
  }
  return sink.close();
}

}  // namespace

int spanlight::hal::app_main(Args args) {
  const char* frame_path = argument_or(args, 1, SPANLIGHT_SELFTEST_FRAME);
  const char* tiles_path = argument_or(args, 2, SPANLIGHT_SELFTEST_TILES);

  if (!selftest::startup_state_ok()) {
    log_line("selftest: start-up state wrong (.data not copied, .bss not zeroed or constructors not run)");
    return 2;
  }

  CostCounter cost;
  cost.begin();
  selftest::fill_test_pattern(framebuffer, kFrameSize);
  cost.end();

  if (!write_whole(frame_path)) {
    log_line(LogLine() << "selftest: cannot write " << frame_path);
    return 1;
  }
  if (!write_tiles(tiles_path)) {
    log_line(LogLine() << "selftest: cannot write tiles to " << tiles_path);
    return 1;
  }
  log_line(LogLine() << "selftest: pattern " << kFrameSize.width << "x" << kFrameSize.height << " filled in "
                     << cost.elapsed() << " " << CostCounter::unit());
  log_line(LogLine() << "selftest: frame fnv1a " << Hex{selftest::fnv1a(framebuffer)} << " -> " << frame_path
                     << ", " << tiles_path);
  log_line(LogLine() << "selftest: stack peak " << stack_peak_bytes() << " bytes");
  return 0;
}
