// Where a frame goes: caller-owned buffers, each with the size it holds, so
// render_frame can refuse a scene that does not fit before it writes a byte.
// Nothing here allocates.
#pragma once

#include <cstdint>
#include <span>

#include "spanlight/1_vertex/vertex_cache.hpp"
#include "spanlight/4_pixel/colour.hpp"
#include "spanlight/4_pixel/depth.hpp"

namespace spanlight {

template <PixelFormat Format, typename DepthT>
struct FrameTarget {
  using Storage = typename ColorTraits<Format>::Storage;
  // width * band_rows pixels each (band_rows = 0: the whole frame, width * height), row 0 at the top.
  std::span<Storage> color;                 // ColorTraits<Format>::per_pixel elements a pixel
  std::span<DepthT> depth;
  // One per projector: map_size^2 texels for a shadowed one, empty for the others.
  std::span<const std::span<DepthT>> shadow_maps;
  // The multipass's one bit per pixel of a band (tie_mask_bytes); the fused pass needs none.
  std::span<std::uint8_t> tie_mask;
  // Each vertex of the largest object once, projected (PreparedScene::max_vertex_count entries).
  std::span<CachedVertex> vertices;
  // Rows per band: the frame is drawn band by band into the same buffers, each
  // band handed to Hooks::band_done when it is finished. 0: one band, the whole frame.
  std::uint16_t band_rows = 0;
};

}  // namespace spanlight
