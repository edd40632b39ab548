// One measured frame for one instantiation. Whole-frame mode brackets
// render_frame exactly as render_baked does; pass mode follows render_frame's
// plan (render.hpp) step by step with a cost region around each pass, so the
// QEMU plugin reports where the instructions go. The frame hash of both modes
// must agree (the sweep checks it against the host render).
#pragma once

#include "bench_features.hpp"
#include "bench_request.hpp"
#include "hal/hal.hpp"
#include "hal/log_line.hpp"
#include "spanlight/render.hpp"

namespace bench {

// Out of line, so the sweep's flash count can leave this bench-only driver out.
template <typename F>
[[gnu::noinline]] spanlight::RenderStatus render_by_pass(const spanlight::PreparedScene& scene, const Target& target,
                                       const spanlight::Precision& precision) {
  using namespace spanlight;
  hal::LogLine<400> names;
  names << "sweep_bench: regions";
  const int bits = precision.depth_bits;
  LightContext lights[F::max_projectors > 0 ? F::max_projectors : 1] = {};
  for (int j = 0; j < scene.projector_count; ++j) {
    const ProjectorData& p = scene.projectors[j];
    lights[j] = {&p, &scene.textures[p.texture], nullptr};
    if constexpr (F::shadows) {
      if (!p.shadows) continue;
      Depth* map = target.shadow_maps[j];
      hal::CostCounter cost;
      cost.begin();
      const std::uint32_t texels = std::uint32_t{p.map_size} * p.map_size;
      for (std::uint32_t i = 0; i < texels; ++i) map[i] = depth_clear(bits);
      ShadowDepthKernel<Depth> kernel{map, DepthFormat{bits}};
      draw_pass<F>(scene, PassView{p.map_size, p.map_size, j}, precision, kernel);
      cost.end();
      names << " shadow" << j;
      lights[j].shadow_map = map;
    }
  }
  const std::uint32_t pixels = std::uint32_t{scene.width} * scene.height;
  const PassView eye{scene.width, scene.height, -1};
  const Rgb8 ambient{scene.ambient[0], scene.ambient[1], scene.ambient[2]};
  hal::CostCounter cost;
  cost.begin();
  for (std::uint32_t i = 0; i < pixels; ++i) {
    target.depth[i] = depth_clear(bits);
    Color::store(target.color + i * Color::per_pixel, Rgb8{0, 0, 0});
  }
  if (precision.fused) {
    FusedKernel<F, Depth, NoObserver> kernel{target, &scene, lights, ambient, nullptr, nullptr, DepthFormat{bits}};
    draw_pass<F>(scene, eye, precision, kernel);
    cost.end();
    hal::log_line(names << " fused");
    return RenderStatus::ok;
  }
  DepthAmbientKernel<F, Depth, NoObserver> depth_pass{target, ambient, DepthFormat{bits}};
  draw_pass<F>(scene, eye, precision, depth_pass);
  cost.end();
  names << " depth_ambient";
  const std::uint32_t mask_bytes = tie_mask_bytes(scene.width, scene.height);
  auto clear_mask = [&] {
    for (std::uint32_t i = 0; i < mask_bytes; ++i) target.tie_mask[i] = 0;
  };
  if constexpr (F::max_projectors > 0) {
    for (int j = 0; j < scene.projector_count; ++j) {
      hal::CostCounter light_cost;
      light_cost.begin();
      clear_mask();
      LightKernel<F, Depth, NoObserver> light_pass{target, lights[j], j, DepthFormat{bits}};
      draw_pass<F>(scene, eye, precision, light_pass);
      light_cost.end();
      names << " light" << j;
    }
  }
  hal::CostCounter modulate_cost;
  modulate_cost.begin();
  clear_mask();
  ModulateKernel<F, Depth, NoObserver> modulate_pass{target, scene.textures, nullptr, nullptr, DepthFormat{bits}};
  draw_pass<F>(scene, eye, precision, modulate_pass);
  modulate_cost.end();
  hal::log_line(names << " modulate");
  return RenderStatus::ok;
}

template <int TableBits, int NewtonSteps>
spanlight::RenderStatus render_measured(const spanlight::PreparedScene& scene, const Request& request) {
  using F = Features<TableBits, NewtonSteps>;
  const Target target = frame_target();
  if (request.passes) return render_by_pass<F>(scene, target, request.precision);
  spanlight::hal::CostCounter cost;
  cost.begin();
  const spanlight::RenderStatus status = spanlight::render_frame<F, Depth>(scene, target, request.precision);
  cost.end();
  return status;
}

// One per instantiation (bench_instance.cpp.in).
#define SPANLIGHT_BENCH_INSTANCE(B, N) \
  spanlight::RenderStatus render_instance_##B##_##N(const spanlight::PreparedScene& scene, const Request& request);
SPANLIGHT_BENCH_INSTANCE(6, 0)
SPANLIGHT_BENCH_INSTANCE(6, 1)
SPANLIGHT_BENCH_INSTANCE(8, 0)
SPANLIGHT_BENCH_INSTANCE(8, 1)
SPANLIGHT_BENCH_INSTANCE(10, 0)
SPANLIGHT_BENCH_INSTANCE(10, 1)
SPANLIGHT_BENCH_INSTANCE(12, 0)
SPANLIGHT_BENCH_INSTANCE(12, 1)
#undef SPANLIGHT_BENCH_INSTANCE

}  // namespace bench
