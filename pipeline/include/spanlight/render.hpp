// The frame plan, in the paper's order: a depth-only render per shadowed
// projector, then eye depth + ambient, one z-equal additive pass per
// projector, and a z-equal modulating surface pass; or the fused pass.
#pragma once

#include <cstdint>

#include "spanlight/passes.hpp"

namespace spanlight {

enum class RenderStatus : std::uint8_t { ok, bad_precision, missing_shadow_map, missing_tie_mask, too_many_projectors };

template <typename F, typename DepthT, typename Observer = NoObserver>
RenderStatus render_frame(const PreparedScene& scene, const FrameTarget<F::format, DepthT>& target,
                          const Precision& precision) {
  using Color = ColorTraits<F::format>;
  if (precision.span_log2 > 6 || precision.span_tolerance_log2 > 10 ||
      (precision.depth_bits != 16 && precision.depth_bits != 24)) {
    return RenderStatus::bad_precision;
  }
  if (precision.depth_bits > static_cast<int>(8 * sizeof(DepthT))) return RenderStatus::bad_precision;
  if (scene.projector_count > F::max_projectors) return RenderStatus::too_many_projectors;
  const int bits = precision.depth_bits;

  LightContext lights[F::max_projectors > 0 ? F::max_projectors : 1] = {};
  for (int j = 0; j < scene.projector_count; ++j) {
    const ProjectorData& p = scene.projectors[j];
    lights[j] = {&p, &scene.textures[p.texture], nullptr};
    if constexpr (F::shadows) {
      if (!p.shadows) continue;
      DepthT* map = target.shadow_maps != nullptr ? target.shadow_maps[j] : nullptr;
      if (map == nullptr) return RenderStatus::missing_shadow_map;
      const std::uint32_t texels = std::uint32_t{p.map_size} * p.map_size;
      for (std::uint32_t i = 0; i < texels; ++i) map[i] = static_cast<DepthT>(depth_clear(bits));
      ShadowDepthKernel<DepthT> kernel{map, DepthFormat{bits}};
      draw_pass<F>(scene, PassView{p.map_size, p.map_size, j}, precision, kernel);
      lights[j].shadow_map = map;
    }
  }

  const std::uint32_t pixels = std::uint32_t{scene.width} * scene.height;
  for (std::uint32_t i = 0; i < pixels; ++i) {
    target.depth[i] = static_cast<DepthT>(depth_clear(bits));
    Color::store(target.color + i * Color::per_pixel, Rgb8{0, 0, 0});
  }
  const PassView eye{scene.width, scene.height, -1};
  const Rgb8 ambient{scene.ambient[0], scene.ambient[1], scene.ambient[2]};

  if (precision.fused) {
    FusedKernel<F, DepthT, Observer> kernel{target, &scene, lights, ambient, nullptr, nullptr, DepthFormat{bits}};
    draw_pass<F>(scene, eye, precision, kernel);
    return RenderStatus::ok;
  }
  DepthAmbientKernel<F, DepthT, Observer> depth_pass{target, ambient, DepthFormat{bits}};
  draw_pass<F>(scene, eye, precision, depth_pass);
  if (target.tie_mask == nullptr) return RenderStatus::missing_tie_mask;
  const std::uint32_t mask_bytes = tie_mask_bytes(scene.width, scene.height);
  auto clear_mask = [&] {
    for (std::uint32_t i = 0; i < mask_bytes; ++i) target.tie_mask[i] = 0;
  };
  if constexpr (F::max_projectors > 0) {
    for (int j = 0; j < scene.projector_count; ++j) {
      clear_mask();
      LightKernel<F, DepthT, Observer> light_pass{target, lights[j], j, DepthFormat{bits}};
      draw_pass<F>(scene, eye, precision, light_pass);
    }
  }
  clear_mask();
  ModulateKernel<F, DepthT, Observer> modulate_pass{target, scene.textures, nullptr, nullptr, DepthFormat{bits}};
  draw_pass<F>(scene, eye, precision, modulate_pass);
  return RenderStatus::ok;
}

}  // namespace spanlight
