// Stage 5b, one pass over the scene: every triangle of every object goes
// through stages 1-3 (transform, clip, divide and snap, setup, rows, spans)
// and hands its runs of pixels to the pass's kernel. Every pass runs this same
// code on the same inputs, so depth is bit-identical from pass to pass (the
// promise the Korobkin demo could not get from GL).
#pragma once

#include <algorithm>
#include <cstdint>
#include <type_traits>

#include "spanlight/1_vertex/clip.hpp"
#include "spanlight/1_vertex/closed.hpp"
#include "spanlight/1_vertex/project.hpp"
#include "spanlight/1_vertex/transform.hpp"
#include "spanlight/1_vertex/vertex_cache.hpp"
#include "spanlight/2_triangle/small.hpp"
#include "spanlight/2_triangle/attributes.hpp"
#include "spanlight/2_triangle/facing.hpp"
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

// Whether a triangle with these window corners can reach a row of the band: the same rows as
// setup (centres 256 r + 128 within [y_min, y_max]), found before any setup or projector
// transform, so the triangles of other bands cost a few compares. Exact, not a heuristic: a
// triangle skipped here is one whose setup gives no row in [row_begin, row_end).
constexpr bool may_cover_rows(const ScreenVertex& a, const ScreenVertex& b, const ScreenVertex& c,
                              const PassView& view) {
  const std::int32_t y_min = fixedpoint::least_of(a.y, b.y, c.y), y_max = fixedpoint::greatest_of(a.y, b.y, c.y);
  // |y| < 2^21 (the guard band): the products stay far inside 32 bits.
  return y_max >= view.row_begin * 256 + 128 && y_min <= view.row_end * 256 - 128;
}

// Guard band in multiples of w: keeps window coordinates within +-2^21
// subpixels (8192 px) and |x + w| <= 7w for the vertex divider.
constexpr std::int64_t guard_band(int width, int height) {
  // The largest g in [1, 6] with (g + 1) * larger <= 16000 (g = 16000 / larger - 1, clamped),
  // found without a divide.
  const int larger = width > height ? width : height;
  int g = 6;
  while (g > 1 && (g + 1) * larger > 16000) --g;
  return g;
}

// Whether a triangle of this object may take the small path in this pass; the
// same answer in every pass of the frame's eye view (so depth agrees between
// passes): uv must step affinely in its sampler's scale with fraction bits to
// spare (a repeating texture, or none), and the eye passes must not need a
// projector's ratios (the small path interpolates none).
constexpr bool small_path_allowed(const PreparedScene& scene, const ObjectData& object, const PassView& view) {
  if (view.light_projector < 0 && scene.projector_count > 0) return false;
  if (object.texture < 0) return true;
  const TextureData& t = scene.textures[object.texture];
  return t.wrap == Wrap::repeat && !mipmapped(t);  // a mip level needs the general walk's lambda
}

// The largest difference of u or v between two of the triangle's vertices (texels * 2^frac).
constexpr std::int32_t uv_range(const ObjectData& object, const std::uint32_t (&index)[3]) {
  std::int32_t range = 0;
  for (std::uint32_t c = 0; c < 2; ++c) {
    const std::int32_t a = object.uvs[index[0] * 2 + c], b = object.uvs[index[1] * 2 + c], d = object.uvs[index[2] * 2 + c];
    const std::int32_t span = fixedpoint::greatest_of(a, b, d) - fixedpoint::least_of(a, b, d);
    range = span > range ? span : range;
  }
  return range;
}

// Depth stays affine within this many Q0.32 units of the vertices' range over a
// small triangle: the corner's value and the two steps are each floored (one
// unit), and a pixel is at most 64 steps from the corner each way.
inline constexpr std::uint32_t small_depth_margin = 256;

// A small triangle's uv quadratics, one a coordinate (2_triangle/small.hpp, perspective_quadratic),
// in the step scale of the object's sampler. A function, not a lambda of draw_small: GCC built
// a lambda's closure at every triangle, hidden or not.
inline void small_uv(const SmallTriangle& t, const ObjectData& object, const std::uint32_t (&index)[3],
                     const PerspectiveWeights& weights, std::int32_t range, const StepScale& scale, QuadraticAttribute (&uv)[2]) {
  const int i0 = t.order[0], i1 = t.order[1], i2 = t.order[2];
  const std::int32_t e0 = weights.e[i0] >> 1, e1 = weights.e[i1] >> 1, e2 = weights.e[i2] >> 1;  // Q0.29
  const AffineAttribute e = t.affine(e0, e1 - e0, e2 - e0, 0);
  for (int c = 0; c < 2; ++c) {
    auto at = [&](int k) { return object.uvs[index[k] * 2 + static_cast<std::uint32_t>(c)]; };
    const int shift = scale.shift[c];
    const std::uint32_t base = static_cast<std::uint32_t>(at(i0) + scale.offset[c]) << shift;
    uv[c] = perspective_quadratic(t, base, shift, range, at(i1) - at(i0), weights.e[i1], at(i2) - at(i0), weights.e[i2], e);
  }
}

// Draws a small triangle (2_triangle/small.hpp): rows by its 32-bit edges, and
// each span as one run with affine depth and quadratic uv. Its edges step down
// the rows in place. The run lives here, out of line from draw_pass, so it is
// not on the stack under the general path's walk (a frame's peak).
template <int P, typename Kernel, typename Hooks>
inline void draw_small(SmallTriangle& t, const ObjectData& object, const std::uint32_t (&index)[3],
                       const ScreenVertex (&v)[3], const PerspectiveWeights& weights, std::int32_t range,
                       const SpanNeeds& needs, const PassView& view, Kernel& kernel, Hooks& hooks) {
  const int i0 = t.order[0], i1 = t.order[1], i2 = t.order[2];
  const AffineAttribute z = t.affine(v[i0].z, v[i1].z - v[i0].z, v[i2].z - v[i0].z, 2);  // Q1.30 -> Q0.32
  // The rows of the band the triangle covers.
  const std::int32_t first = std::max(t.row_begin, view.row_begin);
  const std::int32_t last = std::min(t.row_end, view.row_end);
  // Each field a kernel of this kind may read is set before it reads it; the run is not zeroed as
  // a whole (a memset call at -Os: on M0+ 0.3 % more of mesh_bear). Depth and uv are set per row.
  PixelRun<P> run;
  if constexpr (Kernel::may_need_uv) {
    run.level.level = run.level.base = run.level.step = 0;  // zero, as RunLevel says: a small
    run.level.one_level = false;                            // triangle is never mipmapped
  }
  if constexpr (Kernel::may_need_projectors) {  // the passes the small path serves light no pixel
    run.s = run.t = run.r = {};
    run.front = {};
  }
  // uv is set up at the first row with a pixel that passes the depth test: a triangle hidden
  // behind those drawn before it (the back of a model drawn without culling) costs no uv planes.
  QuadraticAttribute uv[2];  // set by small_uv, read only after it (no zeroing: a memset call)
  bool uv_started = false;
  if (!needs.uv) run.u = run.v = Stepped{};
  hooks.triangle_rows();
  for (std::int32_t row = t.row_begin; row < first; ++row) t.next_row();  // fewer than 64 rows
  run.dz = static_cast<std::int32_t>(z.per_column);
  std::uint32_t z_row = z.at_corner + z.per_row * static_cast<std::uint32_t>(first - t.row0);
  for (std::int32_t row = first; row < last; ++row) {
    std::int32_t lo = -t.column0, hi = view.width - 1 - t.column0;  // columns of the view, relative to the corner
    if (t.columns(lo, hi)) {
      const auto row_index = static_cast<std::uint32_t>((row - view.row_begin) * view.width + t.column0 + lo);
      // Only a run with uv to set up gains from the trim (and only such a pass has `passing`):
      // else the kernel's own test is as cheap.
      PixelRange seen{0, hi - lo + 1};
      if constexpr (Kernel::may_need_uv)
        seen = kernel.passing(row_index, seen.end, z_row + z.per_column * static_cast<std::uint32_t>(lo), run.dz);
      if (seen.first < seen.end) {
        const auto c = static_cast<std::uint32_t>(lo + seen.first);
        run.z = z_row + z.per_column * c;
        if (Kernel::may_need_uv && needs.uv) {
          if (!uv_started) {
            small_uv(t, object, index, weights, range, needs.uv_scale, uv);
            run.u.curve = uv[0].curve();
            run.v.curve = uv[1].curve();
            uv_started = true;
          }
          const auto r = static_cast<std::uint32_t>(row - t.row0);
          uv[0].at(r, c, run.u.value, run.u.step);
          uv[1].at(r, c, run.v.value, run.v.step);
        }
        kernel.run(row_index + static_cast<std::uint32_t>(seen.first), seen.end - seen.first, run);
      }
    }
    t.next_row();
    z_row += z.per_row;
  }
}

template <Features F, typename Divide, typename Kernel, typename Hooks>
inline void draw_pass(const PreparedScene& scene, const FrameMatrices& matrices, const PassView& view,
                      const Knobs& knobs, const Divide& divide, std::uint32_t z_limit, CachedVertex* cache,
                      Kernel& kernel, Hooks& hooks) {
  constexpr int P = F.max_projectors;
  static_assert(PassKernel<Kernel, P>);
  const std::int64_t guard = guard_band(view.width, view.height);
  std::uint16_t projector_texels[projector_slots(P)] = {};
  std::uint8_t projector_texel_bits[projector_slots(P)] = {};
  for (int j = 0; j < scene.projector_count && j < P; ++j) {
    const TextureLevel& image = scene.textures[scene.projectors[j].texture].levels[0];
    projector_texels[j] = image.width > image.height ? image.width : image.height;
    // Q3.28 units per texel of the larger side: 2^28 / size, rounded down in log2.
    projector_texel_bits[j] = static_cast<std::uint8_t>(proj_frac_bits - fixedpoint::bit_length(projector_texels[j] - 1u));  // 1 texel: 0 bits
  }
  SpanControl control{.span_log2 = knobs.span_log2,
                      .tolerance_log2 = knobs.tolerance_log2,
                      .uv = nullptr,  // per object, below
                      .uv_frac_bits = 8,
                      .projector_texels = projector_texels,
                      .projector_texel_bits = projector_texel_bits,
                      .z_limit = z_limit,
                      .mip = knobs.mip};
  const int pc = scene.projector_count;
  const bool banded = view.row_begin > 0 || view.row_end < view.height;  // a whole frame needs no row test

  for (std::uint16_t o = 0; o < scene.object_count; ++o) {
    const ObjectData& object = scene.objects[o];
    const SpanNeeds needs = kernel.object(object);  // per object: untextured ones skip uv
    control.uv = &needs.uv_scale;
    control.uv_frac_bits = object.uv_frac_bits;
    const Mat4Block& to_clip = view.light_projector < 0 ? matrices.clip_from_object[o]
                                                        : matrices.light_clip_from_object[o * pc + view.light_projector];
    const Mat4Block* to_projector = matrices.projector_from_object + o * pc;
    if (object.vertex_count > 8 && object_beyond_a_plane(object.bounds, to_clip, guard)) continue;
    // A closed solid seen from outside shows no back face (1_vertex/closed.hpp): cull them. The
    // lambdas below take it as an argument (captured, it widened their closures on the stack), and
    // a build without closed solids reads the object's own (a copy held across the loop took a
    // stack slot: textured_room's render_frame on M0+ 2,032 B against 2,024; the bound is 2 KiB).
    std::conditional_t<F.closed_solids, Cull, const Cull&> cull = object.cull;
    if constexpr (F.closed_solids) {
      if (closed_and_outside(object, to_clip, guard)) cull = Cull::back;
    }
    const bool small_allowed = small_path_allowed(scene, object, view);
    // The small path's uv step scale, from the texture alone (the same in every pass, as the path's choice).
    const int small_texel_bits = object.texture < 0 ? 32 : surface_of(object, scene.textures).scale.texel_bits;
    cache_vertices(object, to_clip, view.width, view.height, guard, cache);

    // Stages 2 and 3 for one triangle whose window vertices are known (cached, or cut by the clip stage).
    auto draw_general = [&](const ScreenVertex (&corners)[3], const ClipVertex<P>* const (&clip_corners)[3], Cull culling) {
      TriangleSetup setup{};
      if (!setup_triangle(corners, culling, view.height, setup)) return;
      if (setup.row_end <= view.row_begin || setup.row_begin >= view.row_end) return;
      TriangleAttributes<P> attrs{};
      const ClipVertex<P>* const ordered[3] = {clip_corners[setup.order[0]], clip_corners[setup.order[1]],
                                               clip_corners[setup.order[2]]};
      if (needs.uv) set_uv<P>(ordered, attrs);
      // Only a build with trilinear textures keeps the 72 bytes of lambda planes on the stack.
      [[maybe_unused]] std::conditional_t<F.trilinear, LodPlanes, NoLodPlanes> lod{};
      control.lod = nullptr;
      if constexpr (F.trilinear) {
        if (needs.lod) {
          const ScreenVertex* const at[3] = {&corners[setup.order[0]], &corners[setup.order[1]], &corners[setup.order[2]]};
          lod = lod_planes(setup, at, {0, attrs.du1, attrs.du2}, {0, attrs.dv1, attrs.dv2}, object.uv_frac_bits);
          lod.last_level = scene.textures[object.texture].level_count - 1;
          control.lod = &lod;
        }
      }
      for (int j = needs.projector_begin; j < needs.projector_end; ++j) {
        if constexpr (F.facing) {
          // setup's order says the window orientation: order[1] == 1 when the area is positive.
          if (scene.projectors[j].facing_only &&
              !faces_projector(setup.order[1] == 1 ? 1 : -1, clip_corners[0]->proj[j], clip_corners[1]->proj[j],
                               clip_corners[2]->proj[j])) {
            set_unlit<P>(j, attrs);
            continue;
          }
        }
        set_projector<P>(ordered, j, attrs);
      }
      hooks.triangle_rows();
      with_walk_shape<Kernel::may_need_uv, (Kernel::may_need_projectors && P > 0)>(needs, [&](auto uv, auto projectors) {
        PixelRun<P> run{};  // the walk's, zeroed once a triangle
        rasterize_rows(setup, view.width, view.row_begin, view.row_end, [&](std::int32_t row, std::int32_t c0, std::int32_t c1) {
          const auto row_start = static_cast<std::uint32_t>((row - view.row_begin) * view.width);
          if constexpr (F.trilinear) {
            if (control.lod != nullptr) set_lod_row(lod, row);
          }
          walk_span<P, decltype(uv)::value, decltype(projectors)::value, F.trilinear>(
              setup, attrs, needs, control, divide, c0, c1, run,
              [&](std::int32_t column, std::int32_t count, const PixelRun<P>& pixels) SPANLIGHT_LAMBDA_INLINE_ATTR {
                kernel.run(row_start + static_cast<std::uint32_t>(column), count, pixels);
              });
        });
      });
    };
    auto clip_vertex = [&](std::uint32_t index, ClipVertex<P>& cv) {
      const std::int32_t* position = object.positions + index * 3;
      cv.clip = transform(to_clip, position);
      cv.u = needs.uv ? object.uvs[index * 2] : 0;
      cv.v = needs.uv ? object.uvs[index * 2 + 1] : 0;
      for (int j = needs.projector_begin; j < needs.projector_end; ++j) cv.proj[j] = transform(to_projector[j], position);
    };

    // The small path (2_triangle/small.hpp): false when the triangle is not small, or not flat
    // enough for its quadratic uv, and the general path is to draw it. Out of line, so that its
    // state is never on the stack under the general path's walk, where a frame's peak is.
    auto drawn_small = [&](const ScreenVertex (&corners)[3], const std::uint32_t (&index)[3], Cull culling) SPANLIGHT_LAMBDA_NOINLINE_ATTR {
      // A back face leaves before the depth, uv and perspective checks (setup would cull it).
      if (culling == Cull::back && faces_away(corners[0], corners[1], corners[2])) return true;
      std::uint32_t z_lo = 0xFFFFFFFFu, z_hi = 0;
      for (const ScreenVertex& s : corners) {
        const std::uint32_t z = static_cast<std::uint32_t>(s.z) << 2;
        z_lo = z < z_lo ? z : z_lo;
        z_hi = z > z_hi ? z : z_hi;
      }
      // Depth differences below 2^26 (Q0.32): the planes' rounding then stays below 2^26 * 130 * 2^-27 < 65 units.
      const bool depth_ok = z_lo >= small_depth_margin && z_hi <= z_limit - small_depth_margin && z_hi - z_lo < (1u << 26);
      PerspectiveWeights weights;  // set and read only for a textured object (no zeroing: a memset call)
      const std::int32_t range = object.texture < 0 ? 0 : uv_range(object, index);
      const bool uv_ok = object.texture < 0 ||
                         (range < (1 << 26) && perspective_weights_of(corners, weights) &&
                          quadratic_enough(weights, range, object.uv_frac_bits, small_texel_bits, knobs.tolerance_log2));
      if (!depth_ok || !uv_ok) return false;
      // A pass that keeps the nearer depth skips a triangle that every pixel of its box (in the band)
      // already holds nearer: its pixels' depths stay within small_depth_margin of its vertices'.
      auto may_see = [&](std::int32_t column0, std::int32_t columns, std::int32_t r0, std::int32_t r1) {
        if constexpr (requires { kernel.hides(0u, 1, 1, 1, 0u); }) {
          const std::int32_t c0 = std::max(column0, std::int32_t{0}), c1 = std::min(column0 + columns, std::int32_t{view.width});
          r0 = std::max(r0, std::int32_t{view.row_begin});
          r1 = std::min(r1, std::int32_t{view.row_end});
          if (c0 >= c1 || r0 >= r1) return false;
          const auto first = static_cast<std::uint32_t>((r0 - view.row_begin) * view.width + c0);
          return !kernel.hides(first, c1 - c0, r1 - r0, view.width, z_lo - small_depth_margin);
        } else {
          return true;
        }
      };
      SmallTriangle t;
      bool covers = false;
      if (!setup_small(corners, culling, view.height, t, covers, may_see)) return false;
      if (!covers || t.row_end <= view.row_begin || t.row_begin >= view.row_end) return true;  // nothing to draw
      draw_small<P>(t, object, index, corners, weights, range, needs, view, kernel, hooks);
      return true;
    };

    // An object drawn without culling (a model whose back faces are kept) draws the triangles that
    // face the view first and those that face away after them: of a closed model those are hidden,
    // and then cost their setup and a depth test, not a shaded pixel (mesh_bear: 15 % of a frame).
    // The picture is the nearest surface either way; only exact depth ties may go the other way,
    // which the spec leaves to the implementation. A triangle cut by a clip plane goes first.
    const int sides = cull == Cull::none ? 2 : 1;
    for (int side = 0; side < sides; ++side) {
      for (std::uint32_t tri = 0; tri < object.triangle_count; ++tri) {
        const std::uint32_t index[3] = {object.indices[tri * 3], object.indices[tri * 3 + 1], object.indices[tri * 3 + 2]};
        const CachedVertex& a = cache[index[0]];
        const CachedVertex& b = cache[index[1]];
        const CachedVertex& c = cache[index[2]];
        if (sides == 2) {
          const bool away = (a.outside | b.outside | c.outside) == 0 && faces_away(a.screen, b.screen, c.screen);
          if (away != (side == 1)) continue;
        }
        hooks.triangle_begin();
        if (a.outside & b.outside & c.outside) continue;  // all beyond one plane
        // The general path's clip-space vertices: the three corners, or the polygon the clip stage
        // cuts from them. One array serves both: it is the largest thing on a frame's stack.
        ClipPolygon<P> poly;  // v[0, count) is all that is read: no zeroing
        if ((a.outside | b.outside | c.outside) == 0) {
          if (banded && !may_cover_rows(a.screen, b.screen, c.screen, view)) continue;
          const ScreenVertex corners[3] = {a.screen, b.screen, c.screen};
          if (small_allowed && drawn_small(corners, index, cull)) continue;
          for (int k = 0; k < 3; ++k) {  // the window corners come from the cache: no clip position
            ClipVertex<P>& corner = poly.v[k];
            corner.u = needs.uv ? object.uvs[index[k] * 2] : 0;
            corner.v = needs.uv ? object.uvs[index[k] * 2 + 1] : 0;
            for (int j = needs.projector_begin; j < needs.projector_end; ++j)
              corner.proj[j] = transform(to_projector[j], object.positions + index[k] * 3);
          }
          const ClipVertex<P>* const clip_corners[3] = {&poly.v[0], &poly.v[1], &poly.v[2]};
          draw_general(corners, clip_corners, cull);
          continue;
        }
        // A vertex beyond a clip plane: the triangle is cut from its positions again.
        poly.count = 3;
        for (int k = 0; k < 3; ++k) clip_vertex(index[k], poly.v[k]);
        if (!clip_polygon(poly, guard, needs.projector_begin, needs.projector_end)) continue;
        // A fan over the clipped polygon, each vertex projected once as the fan reaches it.
        ScreenVertex corners[3] = {project(poly.v[0].clip, view.width, view.height), {},
                                   project(poly.v[1].clip, view.width, view.height)};
        for (int k = 1; k + 1 < poly.count; ++k) {
          corners[1] = corners[2];
          corners[2] = project(poly.v[k + 1].clip, view.width, view.height);
          const ClipVertex<P>* const clip_corners[3] = {&poly.v[0], &poly.v[k], &poly.v[k + 1]};
          draw_general(corners, clip_corners, cull);
        }
      }
    }
  }
}

}  // namespace spanlight
