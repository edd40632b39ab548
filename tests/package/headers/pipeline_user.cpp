// A user's translation unit: every public header of pipeline/ (every_header.hpp, generated from
// the header folders) and render_frame instantiated as host tools and firmware instantiate it:
// everything on (the host's Features), a baked spotlight's build and a baked scene's smallest one.
// The test compiles it with the strict warning set and -Werror, for the host and for Cortex-M.
#include <cstdint>

#include "every_header.hpp"

namespace user {

using namespace spanlight;

// No projectors, one repeat-wrapped nearest texture, fused only, the reciprocal fixed.
constexpr Features smallest_build() {
  Features f = host_features(PixelFormat::rgb565);
  f.max_projectors = 0;
  f.shadows = f.pcf = f.bilinear = f.clamped = f.tinted = f.multipass = false;
  f.table_bits = 8;
  f.newton = 1;
  f.depth_bits = 16;
  return f;
}

// One shadowed projector, fused only, the reciprocal and depth fixed: a baked spotlight.
constexpr Features one_projector_build() {
  Features f = host_features(PixelFormat::rgb888);
  f.max_projectors = 1;
  f.multipass = false;
  f.table_bits = 8;
  f.newton = 1;
  f.depth_bits = 24;
  return f;
}

RenderStatus host_rgb888(const PreparedScene& scene, const FrameMatrices& matrices,
                         const FrameTarget<PixelFormat::rgb888, std::uint32_t>& target, const Knobs& knobs) {
  return render_frame<host_features(PixelFormat::rgb888)>(scene, matrices, target, knobs);
}

RenderStatus host_rgb565_be(const PreparedScene& scene, const FrameMatrices& matrices,
                            const FrameTarget<PixelFormat::rgb565_be, std::uint16_t>& target, const Knobs& knobs) {
  return render_frame<host_features(PixelFormat::rgb565_be)>(scene, matrices, target, knobs);
}

RenderStatus one_projector(const PreparedScene& scene, const FrameMatrices& matrices,
                           const FrameTarget<PixelFormat::rgb888, std::uint32_t>& target, const Knobs& knobs) {
  return render_frame<one_projector_build()>(scene, matrices, target, knobs);
}

RenderStatus smallest(const PreparedScene& scene, const FrameMatrices& matrices,
                      const FrameTarget<PixelFormat::rgb565, std::uint16_t>& target, const Knobs& knobs) {
  return render_frame<smallest_build()>(scene, matrices, target, knobs);
}

}  // namespace user
