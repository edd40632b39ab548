// Host front-end of the fixed-point pipeline: owns the buffers a firmware
// build would declare statically, and runs render_frame with the knobs'
// format through the one dispatch (spanlight/dispatch.hpp).
#pragma once

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "prepare/prepare.hpp"
#include "spanlight/dispatch.hpp"
#include "spanlight/render.hpp"

namespace spanlight::prepare {

struct FixedFrame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;       // 8 bits a channel (RGB565 expanded), top row first
  std::vector<std::uint8_t> raw;       // the framebuffer's own bytes (RGB888, or RGB565 in its byte order)
  std::vector<std::uint32_t> depth;    // as stored, depth_bits wide
};

// The pipeline refused the frame: the status and what it means.
class RenderRefused : public std::runtime_error {
 public:
  explicit RenderRefused(RenderStatus status)
      : std::runtime_error(std::string("the pipeline refused the frame: ") + describe(status)), status_(status) {}
  RenderStatus status() const { return status_; }

 private:
  RenderStatus status_;
};

// render_frame into buffers of the frame's size; throws RenderRefused. Without `matrices`,
// at the scene's own pose (prepared.matrices); with them, at a run-time pose (pose.hpp).
FixedFrame render_fixed(const PreparedStorage& prepared, const Knobs& knobs);
FixedFrame render_fixed(const PreparedStorage& prepared, const FrameMatrices& matrices, const Knobs& knobs);

// The same with hooks (tests, measurements): instantiates the pipeline where it is called.
template <typename Hooks>
FixedFrame render_fixed_with_hooks(const PreparedStorage& prepared, const FrameMatrices& matrices, const Knobs& knobs,
                                   Hooks&& hooks) {
  return dispatch<host_features(PixelFormat::rgb888), true, false>(knobs, [&]<Features F>() {
    using Color = ColorTraits<F.format>;
    const PreparedScene& scene = prepared.scene;
    const std::size_t pixels = std::size_t{scene.width} * scene.height;
    std::vector<typename Color::Storage> color(pixels * Color::per_pixel);
    FixedFrame frame;
    frame.width = scene.width;
    frame.height = scene.height;
    frame.depth.resize(pixels);
    std::vector<std::vector<std::uint32_t>> maps(scene.projector_count);
    std::vector<std::span<std::uint32_t>> map_spans(scene.projector_count);
    for (std::size_t j = 0; j < scene.projector_count; ++j) {
      const ProjectorData& p = scene.projectors[j];
      if (!p.shadows) continue;
      maps[j].resize(std::size_t{p.map_size} * p.map_size);
      map_spans[j] = maps[j];
    }
    std::vector<std::uint8_t> tie_mask(tie_mask_bytes(static_cast<std::uint32_t>(pixels)));
    std::vector<CachedVertex> vertices(scene.max_vertex_count);
    const FrameTarget<F.format, std::uint32_t> target{color, frame.depth, map_spans, tie_mask, vertices};
    const RenderStatus status = render_frame<F>(scene, matrices, target, knobs, hooks);
    if (status != RenderStatus::ok) throw RenderRefused(status);
    frame.rgb.resize(pixels * 3);
    for (std::size_t i = 0; i < pixels; ++i) {
      const Colour c = Color::load(color.data() + i * Color::per_pixel);
      frame.rgb[i * 3] = static_cast<std::uint8_t>(red(c));
      frame.rgb[i * 3 + 1] = static_cast<std::uint8_t>(green(c));
      frame.rgb[i * 3 + 2] = static_cast<std::uint8_t>(blue(c));
    }
    frame.raw.resize(color.size() * sizeof(typename Color::Storage));
    for (std::size_t i = 0; i < color.size(); ++i) {
      const auto value = static_cast<std::uint32_t>(color[i]);
      for (std::size_t b = 0; b < sizeof(typename Color::Storage); ++b)
        frame.raw[i * sizeof(typename Color::Storage) + b] = static_cast<std::uint8_t>(value >> (8 * b));
    }
    return frame;
  });
}

template <typename Hooks>
FixedFrame render_fixed_with_hooks(const PreparedStorage& prepared, const Knobs& knobs, Hooks&& hooks) {
  return render_fixed_with_hooks(prepared, prepared.matrices, knobs, static_cast<Hooks&&>(hooks));
}

const char* to_string(PixelFormat format);

}  // namespace spanlight::prepare
