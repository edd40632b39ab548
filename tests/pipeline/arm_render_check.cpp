// The whole frame as firmware calls it (render_frame: vertices, triangle setup, spans,
// pixels, every pass), compiled for Cortex-M0+ (see CMakeLists.txt): check_no_soft_float.sh
// then finds no floating-point or division routine among the object's symbols, so no
// triangle and no pixel calls libgcc (M0+ has neither an FPU nor a divide instruction).
// Two builds: a texture-only scene's features, and every feature the pipeline has.
#include "spanlight/render.hpp"

using namespace spanlight;

namespace {

constexpr Features texture_only() {
  Features f;
  f.max_projectors = 0;
  f.shadows = f.pcf = f.trilinear = f.falloff = f.facing = f.clamped = f.tinted = false;
  f.format = PixelFormat::rgb565;
  f.multipass = false;
  f.table_bits = 8;
  f.newton = 1;
  f.depth_bits = 16;
  return f;
}

constexpr Features everything() {
  Features f = host_features(PixelFormat::rgb565);
  f.table_bits = 8;
  f.newton = 1;
  f.depth_bits = 16;
  return f;
}

}  // namespace

extern "C" {

RenderStatus arm_render_texture_only(const PreparedScene* scene, const FrameMatrices* matrices,
                                     const FrameTarget<PixelFormat::rgb565, std::uint16_t>* target, const Knobs* knobs) {
  return render_frame<texture_only()>(*scene, *matrices, *target, *knobs);
}

RenderStatus arm_render_everything(const PreparedScene* scene, const FrameMatrices* matrices,
                                   const FrameTarget<PixelFormat::rgb565, std::uint16_t>* target, const Knobs* knobs) {
  return render_frame<everything()>(*scene, *matrices, *target, *knobs);
}

}  // extern "C"
