// render_baked: renders the scene baked into baked_scene.cpp / baked_config.hpp
// (`spanlight bake`) into static buffers, measures the frame, and writes it out
// through the HAL as a PPM. The same source builds for Cortex-M and the host.
//
// A firmware engineer's own app looks like this: declare the buffers the baked
// configuration asks for, call render_frame, push the colour buffer to a display.
#include <array>
#include <cstdint>

#include "baked_config.hpp"
#include "hal/hal.hpp"
#include "hal/log_line.hpp"

namespace {

using namespace spanlight;
using Color = ColorTraits<baked::Features::format>;

constexpr std::uint32_t pixel_count = std::uint32_t{baked::width} * baked::height;

// Every buffer is static and sized at compile time: no heap anywhere.
std::array<Color::Storage, pixel_count * Color::per_pixel> color;
std::array<baked::Depth, pixel_count> depth;
std::array<baked::Depth, baked::shadow_map_texels ? baked::shadow_map_texels : 1> shadow_pool;
std::array<std::uint8_t, tie_mask_bytes(baked::width, baked::height)> tie_mask;
std::array<std::uint8_t, std::size_t{baked::width} * 3> line;  // one RGB888 row for the sink

// Carves the shadow pool into one map per shadowed projector.
std::array<baked::Depth*, baked::projector_count ? baked::projector_count : 1> shadow_maps() {
  std::array<baked::Depth*, baked::projector_count ? baked::projector_count : 1> maps{};
  std::uint32_t offset = 0;
  for (int j = 0; j < baked::projector_count; ++j) {
    const std::uint32_t size = baked::shadow_map_size[j];
    if (size == 0) continue;
    maps[static_cast<std::size_t>(j)] = shadow_pool.data() + offset;
    offset += size * size;
  }
  return maps;
}

// Rows go out one at a time as RGB888, the way a display driver would take spans.
bool write_frame(const char* path) {
  hal::FrameSink sink;
  if (!sink.open(path, {baked::width, baked::height})) return false;
  for (std::uint16_t y = 0; y < baked::height; ++y) {
    for (std::uint32_t x = 0; x < baked::width; ++x) {
      const Rgb8 c = Color::load(color.data() + (std::uint32_t{y} * baked::width + x) * Color::per_pixel);
      line[x * 3] = c.r;
      line[x * 3 + 1] = c.g;
      line[x * 3 + 2] = c.b;
    }
    if (!sink.flush_rect({0, y, baked::width, 1}, line, line.size())) return false;
  }
  return sink.close();
}

}  // namespace

int spanlight::hal::app_main(Args args) {
  const char* out = args.size() > 1 ? args[1] : "frame.ppm";
  const auto maps = shadow_maps();
  const FrameTarget<baked::Features::format, baked::Depth> target{color.data(), depth.data(), maps.data(),
                                                                   tie_mask.data()};
  CostCounter cost;
  cost.begin();
  const RenderStatus status = render_frame<baked::Features, baked::Depth>(baked::scene, target, baked::precision);
  cost.end();
  if (status != RenderStatus::ok) {
    log_line(LogLine() << "render_baked: render_frame failed with status " << static_cast<int>(status));
    return 1;
  }
  if (!write_frame(out)) {
    log_line(LogLine() << "render_baked: cannot write " << out);
    return 1;
  }
  // Covered pixels: those the depth pass wrote, for "instructions per covered pixel".
  std::uint32_t covered = 0;
  for (const baked::Depth d : depth) covered += d != depth_clear(baked::precision.depth_bits) ? 1u : 0u;
  log_line(LogLine() << "render_baked: " << baked::scene_name << " " << baked::width << "x" << baked::height
                     << " in " << cost.elapsed() << " " << CostCounter::unit() << ", covered " << covered
                     << " pixels, stack peak " << stack_peak_bytes() << " bytes -> " << out);
  return 0;
}
