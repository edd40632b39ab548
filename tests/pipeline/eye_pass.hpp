// The eye pass's geometry (stages 1-3 of 5_frame/draw.hpp) run with a test's
// own kernel, as render_frame runs it: the host's features, the knobs' divide,
// a vertex cache of the scene's max_vertex_count. Shared by tests/pipeline and
// tests/extremes.
#pragma once

#include <cstdint>
#include <vector>

#include "spanlight/render.hpp"

namespace spanlight::ptest {

inline constexpr Features eye_features = host_features(PixelFormat::rgb888);
inline constexpr int eye_projectors = eye_features.max_projectors;
using EyeRun = PixelRun<eye_projectors>;

// Hands every run of every triangle of the eye view to `kernel` (no depth test).
template <typename Kernel>
void draw_eye_pass(const PreparedScene& scene, const FrameMatrices& matrices, Kernel& kernel, const Knobs& knobs = {}) {
  std::vector<CachedVertex> cache(scene.max_vertex_count);
  const DepthFormat<> depth(knobs.depth_bits);
  NoHooks hooks;
  draw_pass<eye_features>(scene, matrices, PassView{scene.width, scene.height, -1, 0, scene.height}, knobs,
                          divide_for<eye_features>(knobs), depth.z_limit, cache.data(), kernel, hooks);
}

// The snapped window position the pipeline gives vertex `index` of object `o` in the eye view.
inline ScreenVertex eye_screen_vertex(const PreparedScene& scene, const FrameMatrices& matrices, std::uint16_t o,
                                      std::uint32_t index) {
  return project(transform(matrices.clip_from_object[o], scene.objects[o].positions + index * 3), scene.width,
                 scene.height);
}

// Counts every pixel a run covers: no depth test, so a pixel two triangles
// both cover is counted twice; `outside` is set by a run beyond the frame.
struct CountingKernel {
  static constexpr bool may_need_uv = false;
  static constexpr bool may_need_projectors = false;
  std::vector<int>* counts;
  bool* outside = nullptr;
  SpanNeeds object(const ObjectData&) const { return {false, {}, 0, 0}; }
  void run(std::uint32_t first, std::int32_t count, const EyeRun&) {
    for (std::int32_t k = 0; k < count; ++k) {
      const std::size_t i = std::size_t{first} + static_cast<std::size_t>(k);
      if (i >= counts->size()) {
        if (outside != nullptr) *outside = true;
        continue;
      }
      ++(*counts)[i];
    }
  }
};

// How many times the eye pass's geometry walk covers each pixel.
inline std::vector<int> eye_coverage_counts(const PreparedScene& scene, const FrameMatrices& matrices,
                                            bool* outside = nullptr) {
  std::vector<int> counts(std::size_t{scene.width} * scene.height, 0);
  CountingKernel kernel{&counts, outside};
  draw_eye_pass(scene, matrices, kernel);
  return counts;
}

}  // namespace spanlight::ptest
