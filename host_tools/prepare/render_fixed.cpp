#include "prepare/render_fixed.hpp"

#include <stdexcept>
#include <string>

#include "prepare/runtime_reciprocal.hpp"
#include "spanlight/render.hpp"

namespace spanlight::prepare {
namespace {

template <PixelFormat Format>
FixedFrame render_with(const PreparedStorage& prepared, const Precision& precision) {
  using F = HostFeaturesWith<Format, RuntimeReciprocal>;  // the table is picked at run time
  using Color = ColorTraits<Format>;
  const PreparedScene& scene = prepared.scene;
  const std::size_t pixels = std::size_t{scene.width} * scene.height;

  std::vector<typename Color::Storage> color(pixels * Color::per_pixel);
  FixedFrame frame;
  frame.width = scene.width;
  frame.height = scene.height;
  frame.depth.resize(pixels);
  std::vector<std::vector<std::uint32_t>> maps(scene.projector_count);
  std::vector<std::uint32_t*> map_pointers(scene.projector_count, nullptr);
  for (int j = 0; j < scene.projector_count; ++j) {
    const ProjectorData& p = scene.projectors[j];
    if (!p.shadows) continue;
    maps[static_cast<std::size_t>(j)].resize(std::size_t{p.map_size} * p.map_size);
    map_pointers[static_cast<std::size_t>(j)] = maps[static_cast<std::size_t>(j)].data();
  }
  std::vector<std::uint8_t> tie_mask(tie_mask_bytes(scene.width, scene.height));
  const FrameTarget<Format, std::uint32_t> target{color.data(), frame.depth.data(), map_pointers.data(),
                                                  tie_mask.data()};
  const RenderStatus status = render_frame<F, std::uint32_t>(scene, target, precision);
  if (status != RenderStatus::ok) throw std::invalid_argument("the pipeline refused the frame (status " + std::to_string(static_cast<int>(status)) + ")");

  frame.rgb.resize(pixels * 3);
  for (std::size_t i = 0; i < pixels; ++i) {
    const Rgb8 c = Color::load(color.data() + i * Color::per_pixel);
    frame.rgb[i * 3] = c.r;
    frame.rgb[i * 3 + 1] = c.g;
    frame.rgb[i * 3 + 2] = c.b;
  }
  frame.raw.resize(color.size() * sizeof(typename Color::Storage));
  for (std::size_t i = 0; i < color.size(); ++i) {
    const auto value = static_cast<std::uint32_t>(color[i]);
    for (std::size_t b = 0; b < sizeof(typename Color::Storage); ++b)
      frame.raw[i * sizeof(typename Color::Storage) + b] = static_cast<std::uint8_t>(value >> (8 * b));
  }
  return frame;
}

}  // namespace

FixedFrame render_fixed(const PreparedStorage& prepared, const FixedOptions& options) {
  const ReciprocalChoice reciprocal(options.table_bits, options.newton_steps);
  if (options.format == PixelFormat::rgb565) return render_with<PixelFormat::rgb565>(prepared, options.precision);
  return render_with<PixelFormat::rgb888>(prepared, options.precision);
}

const char* to_string(PixelFormat format) { return format == PixelFormat::rgb565 ? "rgb565" : "rgb888"; }

}  // namespace spanlight::prepare
