// The buffers a frame of the baked scene needs (baked_config.hpp), static and
// sized at compile time, and the FrameTarget over them: what every app that
// renders the baked scene declares, in one place. No heap anywhere.
//   BakedFrame<baked::Depth, baked::features.multipass>::target()   render_baked
//   BakedFrame<std::uint32_t, true>::target()                        sweep_bench (any depth bits, any passes)
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "baked_config.hpp"

namespace baked_frame {

using Color = spanlight::ColorTraits<baked::features.format>;
inline constexpr std::uint32_t pixel_count = std::uint32_t{baked::width} * baked::height;
inline constexpr std::size_t map_slots = spanlight::projector_slots(baked::projector_count);

template <typename DepthT, bool Multipass>
struct BakedFrame {
  using Target = spanlight::FrameTarget<baked::features.format, DepthT>;

  static inline std::array<Color::Storage, pixel_count * Color::per_pixel> color;
  static inline std::array<DepthT, pixel_count> depth;
  static inline std::array<DepthT, baked::shadow_map_texels ? baked::shadow_map_texels : 1> shadow_pool;
  static inline std::array<std::uint8_t, Multipass ? spanlight::tie_mask_bytes(pixel_count) : 1> tie_mask;
  static inline std::array<spanlight::CachedVertex, baked::max_vertex_count> vertices;
  static inline std::array<std::span<DepthT>, map_slots> maps;

  // The shadow pool carved into one map per shadowed projector (empty for the others);
  // band_rows > 0 draws the frame in bands of that many rows into the same buffers.
  static Target target(std::uint16_t band_rows = 0) {
    std::uint32_t offset = 0;
    for (int j = 0; j < baked::projector_count; ++j) {
      const std::uint32_t size = baked::shadow_map_size[j];
      maps[static_cast<std::size_t>(j)] = std::span<DepthT>(shadow_pool).subspan(offset, size * size);
      offset += size * size;
    }
    return {color, depth, std::span(maps).first(static_cast<std::size_t>(baked::projector_count)), tie_mask, vertices,
            band_rows};
  }

  // Pixels holding a surface's depth: the denominator of "instructions per covered pixel".
  static std::uint32_t covered_pixels(int depth_bits) {
    std::uint32_t covered = 0;
    for (const DepthT d : depth) covered += d != spanlight::depth_clear(depth_bits) ? 1u : 0u;
    return covered;
  }
};

}  // namespace baked_frame
