// Stage 5b, one pass over the scene: every triangle of every object goes
// through stages 1-3 (transform, clip, divide and snap, setup, rows, spans)
// and hands its runs of pixels to the pass's kernel. Every pass runs this same
// code on the same inputs, so depth is bit-identical from pass to pass (the
// promise the Korobkin demo could not get from GL).
#pragma once

#include <cstdint>
#include <type_traits>

#include "spanlight/1_vertex/clip.hpp"
#include "spanlight/1_vertex/project.hpp"
#include "spanlight/1_vertex/transform.hpp"
#include "spanlight/2_triangle/attributes.hpp"
#include "spanlight/2_triangle/setup.hpp"
#include "spanlight/3_span/walk.hpp"
#include "spanlight/5_frame/passes.hpp"
#include "spanlight/features.hpp"
#include "spanlight/frame_matrices.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

// Which matrices a pass draws with and into what viewport, and which of its rows.
struct PassView {
  int width, height;
  int light_projector;           // -1: the camera (clip_from_object); j: projector j's shadow-map view
  std::int32_t row_begin, row_end;  // the rows this pass writes (a band); pixel index = (row - row_begin) * width + column
};

// Guard band in multiples of w: keeps window coordinates within +-2^21
// subpixels (8192 px) and |x + w| <= 7w for the vertex divider.
constexpr std::int64_t guard_band(int width, int height) {
  const int larger = width > height ? width : height;
  const int g = 16000 / larger - 1;
  return g > 6 ? 6 : (g < 1 ? 1 : g);
}

template <Features F, typename Divide, typename Kernel, typename Hooks>
inline void draw_pass(const PreparedScene& scene, const FrameMatrices& matrices, const PassView& view,
                      const Knobs& knobs, const Divide& divide, std::uint32_t z_limit, Kernel& kernel, Hooks& hooks) {
  constexpr int P = F.max_projectors;
  static_assert(PassKernel<Kernel, P>);
  const std::int64_t guard = guard_band(view.width, view.height);
  std::uint16_t projector_texels[projector_slots(P)] = {};
  std::uint8_t projector_texel_bits[projector_slots(P)] = {};
  for (int j = 0; j < scene.projector_count && j < P; ++j) {
    const TextureLevel& image = scene.textures[scene.projectors[j].texture].levels[0];
    projector_texels[j] = image.width > image.height ? image.width : image.height;
    // Q3.28 units per texel of the larger side: 2^28 / size, rounded down in log2.
    projector_texel_bits[j] = static_cast<std::uint8_t>(proj_frac_bits - (32 - fixedpoint::clz32(projector_texels[j] - 1u)));
  }
  SpanControl control{knobs.span_log2, knobs.tolerance_log2, nullptr, 8, projector_texels, projector_texel_bits, z_limit};
  const int pc = scene.projector_count;

  for (std::uint16_t o = 0; o < scene.object_count; ++o) {
    const ObjectData& object = scene.objects[o];
    const SpanNeeds needs = kernel.object(object);  // per object: untextured ones skip uv
    control.uv = &needs.uv_scale;
    control.uv_frac_bits = object.uv_frac_bits;
    const Mat4Block& to_clip = view.light_projector < 0 ? matrices.clip_from_object[o]
                                                        : matrices.light_clip_from_object[o * pc + view.light_projector];
    const Mat4Block* to_projector = matrices.projector_from_object + o * pc;

    for (std::uint32_t tri = 0; tri < object.triangle_count; ++tri) {
      hooks.triangle_begin();
      ClipPolygon<P> poly{};
      poly.count = 3;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t index = object.indices[tri * 3 + static_cast<std::uint32_t>(k)];
        const std::int32_t* position = object.positions + index * 3;
        ClipVertex<P>& cv = poly.v[k];
        cv.clip = transform(to_clip, position);
        cv.u = needs.uv ? object.uvs[index * 2] : 0;
        cv.v = needs.uv ? object.uvs[index * 2 + 1] : 0;
        for (int j = needs.projector_begin; j < needs.projector_end; ++j) cv.proj[j] = transform(to_projector[j], position);
      }
      if (!clip_polygon(poly, guard, needs.projector_begin, needs.projector_end)) continue;

      ScreenVertex screen[max_clipped_vertices];
      for (int k = 0; k < poly.count; ++k) screen[k] = project(poly.v[k].clip, view.width, view.height);

      for (int k = 1; k + 1 < poly.count; ++k) {  // fan over the clipped polygon
        const ScreenVertex corners[3] = {screen[0], screen[k], screen[k + 1]};
        const ClipVertex<P>* clip_corners[3] = {&poly.v[0], &poly.v[k], &poly.v[k + 1]};
        TriangleSetup setup{};
        if (!setup_triangle(corners, object.cull, view.height, setup)) continue;
        if (setup.row_end <= view.row_begin || setup.row_begin >= view.row_end) continue;

        TriangleAttributes<P> attrs{};
        const ClipVertex<P>* const ordered[3] = {clip_corners[setup.order[0]], clip_corners[setup.order[1]],
                                                 clip_corners[setup.order[2]]};
        if (needs.uv) set_uv<P>(ordered, attrs);
        for (int j = needs.projector_begin; j < needs.projector_end; ++j) set_projector<P>(ordered, j, attrs);
        hooks.triangle_rows();

        with_walk_shape<Kernel::may_need_uv, (Kernel::may_need_projectors && P > 0)>(needs, [&](auto uv, auto projectors) {
          rasterize_rows(setup, view.width, [&](std::int32_t row, std::int32_t c0, std::int32_t c1) {
            if (row < view.row_begin || row >= view.row_end) return;
            const auto row_start = static_cast<std::uint32_t>((row - view.row_begin) * view.width);
            walk_span<P, decltype(uv)::value, decltype(projectors)::value>(
                setup, attrs, needs, control, divide, c0, c1,
                [&](std::int32_t column, std::int32_t count, const PixelRun<P>& run) SPANLIGHT_LAMBDA_INLINE_ATTR {
                  kernel.run(row_start + static_cast<std::uint32_t>(column), count, run);
                });
          });
        });
      }
    }
  }
}

}  // namespace spanlight
