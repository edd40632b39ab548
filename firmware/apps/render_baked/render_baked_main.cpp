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
// configuration asks for, call render_frame, push the colour buffer to a display.
#include <array>
#include <cstdint>
#include <span>

#include "app_args.hpp"
#include "baked_config.hpp"
#include "band_sink.hpp"
#include "hal/hal.hpp"
#include "hal/log_line.hpp"

namespace {

using namespace spanlight;
using Color = ColorTraits<baked::features.format>;

constexpr std::uint32_t pixel_count = std::uint32_t{baked::width} * baked::height;

// Every buffer is static and sized at compile time: no heap anywhere.
std::array<Color::Storage, pixel_count * Color::per_pixel> color;
std::array<baked::Depth, pixel_count> depth;
std::array<baked::Depth, baked::shadow_map_texels ? baked::shadow_map_texels : 1> shadow_pool;
std::array<std::uint8_t, baked::features.multipass ? tie_mask_bytes(pixel_count) : 1> tie_mask;
std::array<CachedVertex, baked::max_vertex_count> vertices;
std::array<std::uint8_t, std::size_t{baked::width} * 3> line;  // one RGB888 row for the sink

constexpr std::size_t map_slots = baked::projector_count ? baked::projector_count : 1;

// Carves the shadow pool into one map per shadowed projector.
std::array<std::span<baked::Depth>, map_slots> shadow_maps() {
  std::array<std::span<baked::Depth>, map_slots> maps{};
  std::uint32_t offset = 0;
  for (int j = 0; j < baked::projector_count; ++j) {
    const std::uint32_t size = baked::shadow_map_size[j];
    if (size == 0) continue;
    maps[static_cast<std::size_t>(j)] = std::span<baked::Depth>(shadow_pool).subspan(offset, size * size);
    offset += size * size;
  }
  return maps;
}

}  // namespace

int spanlight::hal::app_main(Args args) {
  const char* out = args.size() > 1 ? args[1] : "frame.ppm";
  std::uint32_t band_rows = 0;
  if (args.size() > 2 && !apps::parse_count(args[2], 0, baked::height, band_rows)) {
    log_line(LogLine() << "render_baked: band rows: expected an integer in 0.." << baked::height << ", got " << args[2]);
    return 2;
  }
  const auto maps = shadow_maps();
  const FrameTarget<baked::features.format, baked::Depth> target{color, depth, std::span(maps).first(baked::projector_count),
                                                                 tie_mask, vertices, static_cast<std::uint16_t>(band_rows)};
  hal::FrameSink sink;
  if (!sink.open(out, {baked::width, baked::height})) {
    log_line(LogLine() << "render_baked: cannot write " << out);
    return 1;
  }
  CostCounter cost;
  apps::BandSink<baked::features.format> bands{{}, band_rows ? &sink : nullptr, line, baked::width, &cost};
  cost.begin();
  const RenderStatus status = render_frame<baked::features>(baked::scene, baked::matrices, target, baked::knobs, bands);
  cost.end();
  if (status != RenderStatus::ok) {
    log_line(LogLine() << "render_baked: render_frame refused the frame: " << describe(status));
    return 1;
  }
  const bool written = band_rows ? bands.ok : apps::write_rows<baked::features.format>(&sink, baked::width, 0, baked::height, color.data(), line);
  if (!written || !sink.close()) {
    log_line(LogLine() << "render_baked: cannot write " << out);
    return 1;
  }
  // Covered pixels: those with a surface's depth, for "instructions per covered pixel" (with
  // bands, of the last band only).
  std::uint32_t covered = 0;
  for (const baked::Depth d : depth) covered += d != depth_clear(baked::knobs.depth_bits) ? 1u : 0u;
  log_line(LogLine() << "render_baked: " << baked::scene_name << " " << baked::width << "x" << baked::height
                     << " in " << cost.elapsed() << " " << CostCounter::unit() << ", band rows " << band_rows << ", covered " << covered
                     << " pixels, stack peak " << stack_peak_bytes() << " bytes -> " << out);
  return 0;
}
