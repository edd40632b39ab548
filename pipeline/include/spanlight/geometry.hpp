// Stages 1-3 for one pass: every triangle of every object is transformed,
// clipped, divided, snapped and set up, then handed to the row and span walk.
// All passes run this same code on the same inputs, so depth is bit-identical
// from pass to pass (the promise the Korobkin demo could not get from GL).
#pragma once

#include <cstdint>
#include <type_traits>

#include "spanlight/clip.hpp"
#include "spanlight/features.hpp"
#include "spanlight/prepared_scene.hpp"
#include "spanlight/span.hpp"

namespace spanlight {

// Which matrix a pass draws with and into what viewport.
struct PassView {
  int width, height;
  int light_projector;  // -1: the camera (clip_from_object); j: projector j's shadow-map view
};

// Guard band in multiples of w: keeps window coordinates within +-2^21
// subpixels (8192 px) and |x + w| <= 7w for the vertex divider.
constexpr std::int64_t guard_band(int width, int height) {
  const int larger = width > height ? width : height;
  const int g = 16000 / larger - 1;
  return g > 6 ? 6 : (g < 1 ? 1 : g);
}

template <int P>
constexpr void normalise_projector(const ClipVertex<P>* const (&v)[3], int j, TriangleAttributes<P>& a) {
  std::uint64_t largest = 0;
  for (const ClipVertex<P>* cv : v) {
    const std::int64_t comps[4] = {cv->proj[j].x, cv->proj[j].y, cv->proj[j].z, cv->proj[j].w};
    for (std::int64_t c : comps) {
      const std::uint64_t m = static_cast<std::uint64_t>(c < 0 ? -c : c);
      if (m > largest) largest = m;
    }
  }
  // Only the ratios s/q, t/q, r/q matter, so one shift for all twelve values.
  const int excess = fixedpoint::bit_length(largest) - 30;
  const int shift = excess > 0 ? excess : 0;
  auto at = [&](int vertex, int c) {
    const Vec4Wide& p = v[vertex]->proj[j];
    const std::int64_t value = c == 0 ? p.x : (c == 1 ? p.y : (c == 2 ? p.z : p.w));
    return static_cast<std::int32_t>(value >> shift);
  };
  for (int c = 0; c < 4; ++c) {
    a.proj0[j][c] = at(0, c);
    a.proj_d1[j][c] = at(1, c) - a.proj0[j][c];
    a.proj_d2[j][c] = at(2, c) - a.proj0[j][c];
  }
}

// What a kernel may ask a walk for (its static may_need_uv / may_need_projectors;
// both when it does not say): only those walk shapes are compiled for it.
template <typename Kernel>
constexpr bool kernel_may_need_uv() {
  if constexpr (requires { Kernel::may_need_uv; }) return Kernel::may_need_uv;
  else return true;
}
template <typename Kernel>
constexpr bool kernel_may_need_projectors() {
  if constexpr (requires { Kernel::may_need_projectors; }) return Kernel::may_need_projectors;
  else return true;
}

// A kernel whose pixel() is const keeps no state of its own per pixel, so the
// walk may use a copy that lives in registers: a store through the colour
// buffer's uint8_t* may alias any object in memory, and every member of the
// kernel itself would be reloaded after each pixel. Other kernels (tests'
// recorders) are called in place.
template <int P, typename Kernel, typename Fn>
inline void with_pixel_kernel(Kernel& kernel, Fn&& fn) {
  if constexpr (requires(const Kernel& k, const PointValues<P>& v) { k.pixel(std::int32_t{0}, v); }) {
    const Kernel local = kernel;
    fn(local);
  } else {
    fn(kernel);
  }
}

// A kernel at one row: columns become pixel indices. run() is there when the
// kernel has one (see PixelRun). Kernel is const for a copy (with_pixel_kernel).
template <int P, typename Kernel>
struct RowPixels {
  Kernel& kernel;
  std::int32_t row_start;
  SPANLIGHT_PIXEL_INLINE void operator()(std::int32_t column, const PointValues<P>& values) const {
    kernel.pixel(row_start + column, values);
  }
  SPANLIGHT_PIXEL_INLINE std::int64_t run(std::int32_t column, std::int32_t count, const PixelRun<P>& r) const
    requires requires(Kernel& k) { k.run(std::int32_t{0}, std::int32_t{1}, r); }
  {
    return kernel.run(row_start + column, count, r);
  }
};

// Kernel interface: needs(), object(const ObjectData&), pixel(index, values),
// and optionally run(first index, count, PixelRun) returning the run's z_acc.
template <typename F, typename Kernel>
inline void draw_pass(const PreparedScene& scene, const PassView& view, const Precision& precision, Kernel& kernel) {
  constexpr int P = F::max_projectors;
  using R = typename F::reciprocal;
  const std::int64_t guard = guard_band(view.width, view.height);
  std::uint16_t projector_texels[P > 0 ? P : 1] = {};
  for (int j = 0; j < scene.projector_count && j < P; ++j) {
    const TextureData& image = scene.textures[scene.projectors[j].texture];
    projector_texels[j] = image.width > image.height ? image.width : image.height;
  }
  SpanControl control{precision.span_log2, precision.span_tolerance_log2, 0, projector_texels};

  for (std::uint16_t o = 0; o < scene.object_count; ++o) {
    const ObjectData& object = scene.objects[o];
    kernel.object(object);
    const SpanNeeds needs = kernel.needs();  // per object: untextured ones skip uv
    control.uv_frac_bits = object.uv_frac_bits;
    const Mat4Block& to_clip =
        view.light_projector < 0 ? object.clip_from_object : object.light_clip_from_object[view.light_projector];

    for (std::uint32_t tri = 0; tri < object.triangle_count; ++tri) {
      ClipPolygon<P> poly{};
      poly.count = 3;
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t index = object.indices[tri * 3 + static_cast<std::uint32_t>(k)];
        const std::int32_t* position = object.positions + index * 3;
        ClipVertex<P>& cv = poly.v[k];
        cv.clip = transform(to_clip, position);
        cv.u = needs.uv ? object.uvs[index * 2] : 0;
        cv.v = needs.uv ? object.uvs[index * 2 + 1] : 0;
        for (int j = needs.projector_begin; j < needs.projector_end; ++j) cv.proj[j] = transform(object.projector_from_object[j], position);
      }
      if (!clip_polygon(poly, guard, needs.projector_begin, needs.projector_end)) continue;

      ScreenVertex screen[max_clipped_vertices];
      for (int k = 0; k < poly.count; ++k) screen[k] = project(poly.v[k].clip, view.width, view.height);

      for (int k = 1; k + 1 < poly.count; ++k) {  // fan over the clipped polygon
        const ScreenVertex corners[3] = {screen[0], screen[k], screen[k + 1]};
        const ClipVertex<P>* clip_corners[3] = {&poly.v[0], &poly.v[k], &poly.v[k + 1]};
        TriangleSetup setup{};
        if (!setup_triangle(corners, object.cull, view.width, view.height, setup)) continue;

        TriangleAttributes<P> attrs{};
        const ClipVertex<P>* const ordered[3] = {clip_corners[setup.order[0]], clip_corners[setup.order[1]],
                                                 clip_corners[setup.order[2]]};
        if (needs.uv) {
          attrs.u0 = ordered[0]->u;
          attrs.du1 = ordered[1]->u - attrs.u0;
          attrs.du2 = ordered[2]->u - attrs.u0;
          attrs.v0 = ordered[0]->v;
          attrs.dv1 = ordered[1]->v - attrs.v0;
          attrs.dv2 = ordered[2]->v - attrs.v0;
        }
        for (int j = needs.projector_begin; j < needs.projector_end; ++j) normalise_projector<P>(ordered, j, attrs);

        with_pixel_kernel<P>(kernel, [&](auto& pixel_kernel) {
          with_walk_shape<kernel_may_need_uv<Kernel>(), (kernel_may_need_projectors<Kernel>() && P > 0)>(needs, [&](auto uv, auto projectors) {
            rasterize_rows(setup, view.width, [&](std::int32_t row, std::int32_t c0, std::int32_t c1) {
              const std::int32_t row_start = row * view.width;
              walk_span<P, R, decltype(uv)::value, decltype(projectors)::value>(
                  setup, attrs, needs, control, c0, c1, RowPixels<P, std::remove_reference_t<decltype(pixel_kernel)>>{pixel_kernel, row_start});
            });
          });
        });
      }
    }
  }
}

}  // namespace spanlight
