// The whole frame as firmware calls it (render_frame: vertices, triangle setup, spans,
// pixels, every pass), compiled for Cortex-M0+ (see CMakeLists.txt): check_no_soft_float.sh
// then finds no floating-point or division routine among the object's symbols, so no
// triangle and no pixel calls libgcc (M0+ has neither an FPU nor a divide instruction).
// Two builds: a texture-only scene's features, and every feature the pipeline has.
#include "spanlight/render.hpp"

using namespace spanlight;

namespace {

// A textured room's build: no projector, repeat textures, fused only, reciprocal and depth fixed.
constexpr Features texture_only{.max_projectors = 0, .shadows = false, .pcf = false, .clamped = false,
                                .tinted = false, .trilinear = false, .falloff = false, .facing = false, .closed_solids = false,
                                .format = PixelFormat::rgb565, .multipass = false, .table_bits = 8, .newton = 1,
                                .depth_bits = 16};

// Every feature the pipeline has, both pass plans, with the same fixed reciprocal and depth.
constexpr Features everything{.format = PixelFormat::rgb565, .table_bits = 8, .newton = 1, .depth_bits = 16};

}  // namespace

extern "C" {

RenderStatus arm_render_texture_only(const PreparedScene* scene, const FrameMatrices* matrices,
                                     const FrameTarget<PixelFormat::rgb565, std::uint16_t>* target, const Knobs* knobs) {
  return render_frame<texture_only>(*scene, *matrices, *target, *knobs);
}

RenderStatus arm_render_everything(const PreparedScene* scene, const FrameMatrices* matrices,
                                   const FrameTarget<PixelFormat::rgb565, std::uint16_t>* target, const Knobs* knobs) {
  return render_frame<everything>(*scene, *matrices, *target, *knobs);
}

}  // extern "C"
