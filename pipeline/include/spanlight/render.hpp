// The frame plan, in the paper's order: a depth-only render per shadowed
// projector (its shadow map, once per frame), then, band by band, eye depth +
// ambient, one z-equal additive pass per projector and a z-equal modulating
// surface pass; or the fused pass, one pass with the same bytes.
//
//   RenderStatus s = render_frame<baked::features>(baked::scene, baked::matrices, target, baked::knobs);
//
// Every buffer comes from the caller with its size (FrameTarget); a scene that
// does not fit them, or knobs the build cannot honour, is refused with a
// RenderStatus before a byte is written. Nothing here allocates or throws.
#pragma once

#include <cstdint>

#include "spanlight/3_span/divide.hpp"
#include "spanlight/5_frame/clear.hpp"
#include "spanlight/5_frame/draw.hpp"
#include "spanlight/5_frame/passes.hpp"
#include "spanlight/features.hpp"
#include "spanlight/frame_matrices.hpp"
#include "spanlight/frame_target.hpp"
#include "spanlight/hooks.hpp"
#include "spanlight/knobs.hpp"
#include "spanlight/scene.hpp"
#include "spanlight/scene_features.hpp"

namespace spanlight {

enum class RenderStatus : std::uint8_t {
  ok,
  bad_knobs,             // a knob outside its allowed values, or one this build was not compiled for (Features)
  scene_needs_feature,   // the scene uses something this build left out (Features): rebake
  too_many_projectors,   // more projectors than Features::max_projectors
  colour_too_small,      // the colour buffer holds fewer pixels than width * (band rows)
  depth_too_small,       // the depth buffer likewise
  bad_band,              // band_rows above the frame's height
  shadow_map_missing,    // a shadowed projector has no map, or one of the wrong size (map_size^2 texels)
  tie_mask_too_small,    // the multipass needs tie_mask_bytes(width * band rows) bytes
  depth_type_too_narrow, // 24-bit depth asked of 16-bit depth storage
  vertices_too_small,    // the vertex buffer holds fewer than the scene's max_vertex_count
  bad_pose,              // render_frame_at_pose: the pose's matrices cannot be built (PoseResult, pose.hpp)
  shadow_bias_out_of_range,  // a shadowed projector's bias outside [0, max_shadow_bias] (scene.hpp)
};

// What each status means, for messages.
constexpr const char* describe(RenderStatus s) {
  switch (s) {
    case RenderStatus::ok: return "ok";
    case RenderStatus::bad_knobs: return "knobs outside their allowed values or not compiled into this build";
    case RenderStatus::scene_needs_feature: return "the scene uses a feature this build left out: bake it again";
    case RenderStatus::too_many_projectors: return "more projectors than the build's max_projectors";
    case RenderStatus::colour_too_small: return "the colour buffer is smaller than the frame (or band)";
    case RenderStatus::depth_too_small: return "the depth buffer is smaller than the frame (or band)";
    case RenderStatus::bad_band: return "band_rows is larger than the frame's height";
    case RenderStatus::shadow_map_missing: return "a shadowed projector has no shadow map of map_size^2 texels";
    case RenderStatus::tie_mask_too_small: return "the multipass's tie mask is smaller than tie_mask_bytes(pixels)";
    case RenderStatus::depth_type_too_narrow: return "24-bit depth needs 32-bit depth storage";
    case RenderStatus::vertices_too_small: return "the vertex buffer is smaller than the scene's largest object (max_vertex_count)";
    case RenderStatus::bad_pose: return "the pose's matrices cannot be built (a view, frustum or model out of range)";
    case RenderStatus::shadow_bias_out_of_range: return "a shadowed projector's bias is outside [0, max_shadow_bias] (1.99 in Q1.30)";
  }
  return "unknown status";
}

template <Features F, typename DepthT>
constexpr RenderStatus check_frame(const PreparedScene& scene, const FrameTarget<F.format, DepthT>& target,
                                   const Knobs& knobs) {
  using Color = ColorTraits<F.format>;
  if (!knobs_valid(knobs) || !supports(F, knobs)) return RenderStatus::bad_knobs;
  if (knobs.depth_bits > 8 * sizeof(DepthT)) return RenderStatus::depth_type_too_narrow;
  if (scene.projector_count > F.max_projectors) return RenderStatus::too_many_projectors;
  if (!covers(F, features_of(scene, knobs))) return RenderStatus::scene_needs_feature;
  if (target.band_rows > scene.height) return RenderStatus::bad_band;
  const std::uint32_t rows = target.band_rows == 0 ? scene.height : target.band_rows;
  const std::uint32_t pixels = std::uint32_t{scene.width} * rows;
  if (target.color.size() < std::size_t{pixels} * Color::per_pixel) return RenderStatus::colour_too_small;
  if (target.depth.size() < pixels) return RenderStatus::depth_too_small;
  if (target.vertices.size() < scene.max_vertex_count) return RenderStatus::vertices_too_small;
  if (knobs.passes == Passes::multipass && target.tie_mask.size() < tie_mask_bytes(pixels))
    return RenderStatus::tie_mask_too_small;
  for (int j = 0; j < scene.projector_count; ++j) {
    const ProjectorData& p = scene.projectors[j];
    if (!p.shadows) continue;
    if (static_cast<std::size_t>(j) >= target.shadow_maps.size() ||
        target.shadow_maps[static_cast<std::size_t>(j)].size() != std::size_t{p.map_size} * p.map_size)
      return RenderStatus::shadow_map_missing;
    if (p.bias < 0 || p.bias > max_shadow_bias) return RenderStatus::shadow_bias_out_of_range;
  }
  return RenderStatus::ok;
}

template <Features F, typename DepthT, typename Hooks = NoHooks>
RenderStatus render_frame(const PreparedScene& scene, const FrameMatrices& matrices,
                          const FrameTarget<F.format, DepthT>& target, const Knobs& knobs, Hooks&& hooks = Hooks{}) {
  using Color = ColorTraits<F.format>;
  constexpr int P = F.max_projectors;
  const RenderStatus status = check_frame<F>(scene, target, knobs);
  if (status != RenderStatus::ok) return status;
  const auto divide = divide_for<F>(knobs);
  const DepthFormat<F.depth_bits> depth(knobs.depth_bits);

  Light<DepthT> lights[projector_slots(P)] = {};
  for (int j = 0; j < scene.projector_count; ++j) {
    const ProjectorData& p = scene.projectors[j];
    lights[j] = {.projector = &p,
                 .image = &scene.textures[p.texture],
                 .shadow_map = nullptr,  // set once the map is drawn, below
                 .falloff = p.falloff >= 0 ? &scene.textures[p.falloff] : nullptr};
    if constexpr (F.shadows) {
      if (!p.shadows) continue;
      const std::span<DepthT> map = target.shadow_maps[static_cast<std::size_t>(j)];
      clear_depth(map.data(), map.size(), depth.clear);
      hooks.pass_begin(Pass::shadow_depth, j);
      ShadowDepthKernel<F, DepthT, std::remove_reference_t<Hooks>> kernel{map.data(), depth, hooks};
      draw_pass<F>(scene, matrices, PassView{p.map_size, p.map_size, j, 0, p.map_size}, knobs, divide, depth.z_limit, target.vertices.data(), kernel, hooks);
      hooks.pass_end(Pass::shadow_depth, j);
      lights[j].shadow_map = map.data();
    }
  }

  const std::uint16_t band_rows = target.band_rows == 0 ? scene.height : target.band_rows;
  const Colour ambient = Color::quantize(colour_of(scene.ambient[0], scene.ambient[1], scene.ambient[2]));
  for (std::uint16_t y0 = 0; y0 < scene.height; y0 = static_cast<std::uint16_t>(y0 + band_rows)) {
    const std::uint16_t rows = scene.height - y0 < band_rows ? static_cast<std::uint16_t>(scene.height - y0) : band_rows;
    const std::uint32_t pixels = std::uint32_t{scene.width} * rows;
    clear_depth(target.depth.data(), pixels, depth.clear);
    fill_bytes(target.color.data(), std::size_t{pixels} * Color::per_pixel * sizeof(target.color[0]), 0);  // black: all bytes 0 in every format
    const PassView eye{scene.width, scene.height, -1, y0, y0 + rows};
    const BandBuffers<F.format, DepthT> band{target.color.data(), target.depth.data(), target.tie_mask.data()};
    using H = std::remove_reference_t<Hooks>;

    if (F.fused && knobs.passes == Passes::fused) {
      if constexpr (F.fused) {
        FusedKernel<F, DepthT, H> kernel{band, scene.textures, lights, scene.projector_count, ambient, depth, hooks};
        hooks.pass_begin(Pass::fused, -1);
        draw_pass<F>(scene, matrices, eye, knobs, divide, depth.z_limit, target.vertices.data(), kernel, hooks);
        hooks.pass_end(Pass::fused, -1);
      }
    } else if constexpr (F.multipass) {
      auto clear_mask = [&] { fill_bytes(target.tie_mask.data(), tie_mask_bytes(pixels), 0); };
      DepthAmbientKernel<F, DepthT, H> depth_pass{band, ambient, depth, hooks};
      hooks.pass_begin(Pass::depth_ambient, -1);
      draw_pass<F>(scene, matrices, eye, knobs, divide, depth.z_limit, target.vertices.data(), depth_pass, hooks);
      hooks.pass_end(Pass::depth_ambient, -1);
      if constexpr (P > 0) {
        for (int j = 0; j < scene.projector_count; ++j) {
          clear_mask();
          LightKernel<F, DepthT, H> light_pass{band, lights[j], j, depth, hooks};
          hooks.pass_begin(Pass::light, j);
          draw_pass<F>(scene, matrices, eye, knobs, divide, depth.z_limit, target.vertices.data(), light_pass, hooks);
          hooks.pass_end(Pass::light, j);
        }
      }
      clear_mask();
      ModulateKernel<F, DepthT, H> modulate_pass{band, scene.textures, depth, hooks};
      hooks.pass_begin(Pass::modulate, -1);
      draw_pass<F>(scene, matrices, eye, knobs, divide, depth.z_limit, target.vertices.data(), modulate_pass, hooks);
      hooks.pass_end(Pass::modulate, -1);
    }
    hooks.band_done(y0, rows, target.color.data());
  }
  return RenderStatus::ok;
}

}  // namespace spanlight
