#include "prepare/render_fixed.hpp"

#include <stdexcept>
#include <string>

#include "spanlight/render.hpp"

namespace spanlight::prepare {
namespace {

template <PixelFormat Format, int TableBits, int NewtonSteps>
FixedFrame render_with(const PreparedStorage& prepared, const Precision& precision) {
  using F = HostFeatures<Format, TableBits, NewtonSteps>;
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

template <PixelFormat Format, int TableBits>
FixedFrame dispatch_steps(const PreparedStorage& p, const FixedOptions& o) {
  switch (o.newton_steps) {
    case 0: return render_with<Format, TableBits, 0>(p, o.precision);
    case 1: return render_with<Format, TableBits, 1>(p, o.precision);
    case 2: return render_with<Format, TableBits, 2>(p, o.precision);
    default: throw std::invalid_argument("newton steps must be 0, 1 or 2");
  }
}

template <PixelFormat Format>
FixedFrame dispatch_table(const PreparedStorage& p, const FixedOptions& o) {
  switch (o.table_bits) {
    case 6: return dispatch_steps<Format, 6>(p, o);
    case 8: return dispatch_steps<Format, 8>(p, o);
    case 10: return dispatch_steps<Format, 10>(p, o);
    case 12: return dispatch_steps<Format, 12>(p, o);
    default: throw std::invalid_argument("reciprocal table bits must be 6, 8, 10 or 12");
  }
}

}  // namespace

FixedFrame render_fixed(const PreparedStorage& prepared, const FixedOptions& options) {
  if (options.format == PixelFormat::rgb565) return dispatch_table<PixelFormat::rgb565>(prepared, options);
  return dispatch_table<PixelFormat::rgb888>(prepared, options);
}

const char* to_string(PixelFormat format) { return format == PixelFormat::rgb565 ? "rgb565" : "rgb888"; }

}  // namespace spanlight::prepare
