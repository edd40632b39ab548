// render_baked: renders the scene baked into baked_scene.cpp / baked_config.hpp
// (`spanlight bake`) into static buffers, measures the frame, and writes it out
// through the HAL as a PPM. The same source builds for Cortex-M and the host.
//   render_<scene> [OUT.ppm [BAND_ROWS]]
// BAND_ROWS > 0 draws the frame in bands of that many rows (the buffers hold the whole
// frame either way), each band pushed to the sink as it is finished; the measured
// regions hold only rendering (common/band_sink.hpp), so their sum compares with the
// whole frame's single region.
//
// A firmware engineer's own app looks like this: declare the buffers the baked
// configuration asks for (baked_frame.hpp), call render_frame, push the colour buffer
// to a display.
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>

#include "app_args.hpp"
#include "baked_frame.hpp"
#include "band_sink.hpp"
#include "hal/hal.hpp"
#include "hal/log_line.hpp"

namespace {

using namespace spanlight;
using Frame = baked_frame::BakedFrame<baked::Depth, baked::features.multipass>;

std::array<std::uint8_t, std::size_t{baked::width} * 3> line;  // one RGB888 row for the sink

}  // namespace

int spanlight::hal::app_main(Args args) {
  const char* out = args.size() > 1 ? args[1] : "frame.ppm";
  std::uint32_t band_rows = 0;
  if (args.size() > 2 && !apps::parse_count(args[2], 0, baked::height, band_rows)) {
    log_line(LogLine() << "render_baked: band rows: expected an integer in 0.." << baked::height << ", got " << args[2]);
    return 2;
  }
  const Frame::Target target = Frame::target(static_cast<std::uint16_t>(band_rows));
  hal::FrameSink sink;
  if (!sink.open(out, {baked::width, baked::height})) {
    log_line(LogLine() << "render_baked: cannot write " << out);
    return 1;
  }
  CostCounter cost;
  apps::BandSink<baked::features.format> bands{{}, band_rows ? &sink : nullptr, line, baked::width, &cost};
  const std::size_t app_peak = stack_peak_bytes();  // before stack_mark forgets it
  const std::size_t depth_at_call = stack_mark();
  cost.begin();
  const RenderStatus status = render_frame<baked::features>(baked::scene, baked::matrices, target, baked::knobs, bands);
  cost.end();
  const std::size_t render_stack = stack_peak_bytes() - depth_at_call;  // the frame's own stack, hooks included
  if (status != RenderStatus::ok) {
    log_line(LogLine() << "render_baked: render_frame refused the frame: " << describe(status));
    return 1;
  }
  const bool written =
      band_rows ? bands.ok : apps::write_rows<baked::features.format>(&sink, baked::width, 0, baked::height, Frame::color.data(), line);
  if (!written || !sink.close()) {
    log_line(LogLine() << "render_baked: cannot write " << out);
    return 1;
  }
  // Covered pixels, for "instructions per covered pixel" (with bands, of the last band only).
  const std::uint32_t covered = Frame::covered_pixels(baked::knobs.depth_bits);
  log_line(LogLine() << "render_baked: " << baked::scene_name << " " << baked::width << "x" << baked::height
                     << " in " << cost.elapsed() << " " << CostCounter::unit() << ", band rows " << band_rows << ", covered " << covered
                     << " pixels, stack peak " << std::max(app_peak, stack_peak_bytes()) << " bytes, render_frame stack "
                     << render_stack << " bytes -> " << out);
  return 0;
}
