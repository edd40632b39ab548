// Renders the scene that CMakeLists.txt bakes at build time (spanlight_bake) and hands the
// frame to the board. No HAL and no heap: every buffer is static, sized by the baked
// configuration, and render_frame reports problems as a RenderStatus, not an exception.
#include <array>
#include <cstdint>
#include <span>

#include "baked_config.hpp"  // baked::features, baked::knobs, baked::Depth, width, height, scene, matrices
#include "board.hpp"

namespace {

using Color = spanlight::ColorTraits<baked::features.format>;  // RGB565: one std::uint16_t a pixel
constexpr std::uint32_t pixel_count = std::uint32_t{baked::width} * baked::height;

static_assert(baked::projector_count == 1 && baked::shadow_map_size[0] != 0,
              "this main() is written for the scene's one shadowed projector");

std::array<Color::Storage, pixel_count * Color::per_pixel> color;
std::array<baked::Depth, pixel_count> depth;
std::array<baked::Depth, baked::shadow_map_texels> shadow_map;
// Only the multipass needs a tie mask; the fused pass (the default) draws without one.
std::array<std::uint8_t, baked::features.multipass ? spanlight::tie_mask_bytes(pixel_count) : 0> tie_mask;
// Each vertex of the largest object once, projected per pass.
std::array<spanlight::CachedVertex, baked::max_vertex_count> vertices;

}  // namespace

int main() {
  const std::array<std::span<baked::Depth>, baked::projector_count> shadow_maps{shadow_map};
  const spanlight::FrameTarget<baked::features.format, baked::Depth> target{color, depth, shadow_maps, tie_mask,
                                                                            vertices};
  const spanlight::RenderStatus status =
      spanlight::render_frame<baked::features>(baked::scene, baked::matrices, target, baked::knobs);
  if (status != spanlight::RenderStatus::ok) board_stop(10 + static_cast<int>(status));

  board_stop(board_send_frame(color.data(), baked::width, baked::height) ? 0 : 1);
}
