// render_baked: renders the scene baked into baked_scene.cpp / baked_config.hpp
// (`spanlight bake`) into static buffers, measures the frame, and writes it out
// through the HAL as a PPM. The same source builds for Cortex-M and the host.
//
// A firmware engineer's own app looks like this: declare the buffers the baked (baked_frame.hpp)
// configuration asks for, call render_frame, push the colour buffer to a display.
#include <array>
#include <cstdint>
#include <span>

#include "baked_frame.hpp"
#include "hal/hal.hpp"
#include "hal/log_line.hpp"

namespace {

using namespace spanlight;
using Frame = baked_frame::BakedFrame<baked::Depth, baked::features.multipass>;
using baked_frame::Color;

std::array<std::uint8_t, std::size_t{baked::width} * 3> line;  // one RGB888 row for the sink

// Rows go out one at a time as RGB888, the way a display driver would take spans.
bool write_frame(const char* path) {
  hal::FrameSink sink;
  if (!sink.open(path, {baked::width, baked::height})) return false;
  for (std::uint16_t y = 0; y < baked::height; ++y) {
    for (std::uint32_t x = 0; x < baked::width; ++x) {
      const Colour c = Color::load(Frame::color.data() + (std::uint32_t{y} * baked::width + x) * Color::per_pixel);
      line[x * 3] = static_cast<std::uint8_t>(red(c));
      line[x * 3 + 1] = static_cast<std::uint8_t>(green(c));
      line[x * 3 + 2] = static_cast<std::uint8_t>(blue(c));
    }
    if (!sink.flush_rect({0, y, baked::width, 1}, line, line.size())) return false;
  }
  return sink.close();
}

}  // namespace

int spanlight::hal::app_main(Args args) {
  const char* out = args.size() > 1 ? args[1] : "frame.ppm";
  const Frame::Target target = Frame::target();
  CostCounter cost;
  cost.begin();
  const RenderStatus status = render_frame<baked::features>(baked::scene, baked::matrices, target, baked::knobs);
  cost.end();
  if (status != RenderStatus::ok) {
    log_line(LogLine() << "render_baked: render_frame refused the frame: " << describe(status));
    return 1;
  }
  if (!write_frame(out)) {
    log_line(LogLine() << "render_baked: cannot write " << out);
    return 1;
  }
  const std::uint32_t covered = Frame::covered_pixels(baked::knobs.depth_bits);
  log_line(LogLine() << "render_baked: " << baked::scene_name << " " << baked::width << "x" << baked::height
                     << " in " << cost.elapsed() << " " << CostCounter::unit() << ", covered " << covered
                     << " pixels, stack peak " << stack_peak_bytes() << " bytes -> " << out);
  return 0;
}
