// Stage 5a, the passes' work on a run of pixels, in the paper's order:
//   shadow depth    : z <  D   -> D = z                              (per shadowed projector, its map)
//   depth + ambient : z <  Z   -> Z = z, C = ambient
//   light j         : z == Z   -> C = min(1, C + lit_j * shadow_j * colour_j * image_j)
//   modulate        : z == Z   -> C = C * surface
//   fused           : z <  Z   -> all of the above at once, with the same
//                                 quantisation steps, so the bytes are the same.
// A kernel is what the span walk hands its runs to (the PassKernel concept).
#pragma once

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include "spanlight/3_span/walk.hpp"
#include "spanlight/4_pixel/colour.hpp"
#include "spanlight/4_pixel/depth.hpp"
#include "spanlight/4_pixel/light.hpp"
#include "spanlight/4_pixel/surface.hpp"
#include "spanlight/5_frame/thumb1_run.hpp"
#include "spanlight/features.hpp"
#include "spanlight/hooks.hpp"
#include "spanlight/inline.hpp"

namespace spanlight {

// Pixels [first, end) of a run (passing_range).
struct PixelRange {
  std::int32_t first, end;
};

// What the geometry walk asks of a pass: per object, what to interpolate; per
// run of pixels, the work. may_need_uv / may_need_projectors say at compile time
// which walk shapes can occur, so no other is compiled for the pass. A pass that
// may need uv also says from which pixel of a run its depth test may take one
// (`passing`): the small path sets up uv only for a row that has one. A pass that keeps the
// nearer depth may say whether a box is hidden (`hides`): the small path then skips the rest
// of a triangle's setup.
template <typename K, int P>
concept PassKernel = requires(K& k, const ObjectData& o, const PixelRun<P>& r) {
  { K::may_need_uv } -> std::convertible_to<bool>;
  { K::may_need_projectors } -> std::convertible_to<bool>;
  { k.object(o) } -> std::same_as<SpanNeeds>;
  k.run(std::uint32_t{0}, std::int32_t{1}, r);
} && (!K::may_need_uv || requires(const K& k) {
  { k.passing(std::uint32_t{0}, std::int32_t{1}, std::uint32_t{0}, std::int32_t{0}) } -> std::same_as<PixelRange>;
});

// The buffers of the band a pass writes: pixel (row, column) of the band is index row * width + column.
template <PixelFormat Format, typename DepthT>
struct BandBuffers {
  typename ColorTraits<Format>::Storage* color;
  DepthT* depth;
  std::uint8_t* tie_mask;
};

// The z-equal test of the light and modulate passes: the depth this surface
// stores here is the one the depth pass kept, and no other surface with the
// same depth claimed the pixel first.
template <typename DepthT, typename Format>
[[gnu::always_inline]] inline bool z_equal(const DepthT* depth, const Format& f, std::uint32_t i, std::uint32_t z) {
  const std::uint32_t d = f.store(z);
  return d != f.clear && d == depth[i];
}
template <typename DepthT, typename Format>
[[gnu::always_inline]] inline bool z_equal_and_first(const DepthT* depth, std::uint8_t* tie_mask, const Format& f,
                                                     std::uint32_t i, std::uint32_t z) {
  return z_equal(depth, f, i, z) && claim_pixel(tie_mask, i);
}

// Calls body(k, z) for pixels k = 0 .. count - 1 of a run, stepping depth.
template <typename Body>
[[gnu::always_inline]] inline void for_each_pixel(std::int32_t count, std::uint32_t z, std::int32_t dz, Body&& body) {
  for (std::int32_t k = 0; k < count; ++k) {
    body(k, z);
    z += static_cast<std::uint32_t>(dz);
  }
}

// The same, stepping uv too (body(k, z, x, y), x and y in the sampler's scale).
template <typename Body>
[[gnu::always_inline]] inline void for_each_pixel(std::int32_t count, std::uint32_t z, std::int32_t dz, Stepped u,
                                                  Stepped v, Body&& body) {
  for (std::int32_t k = 0; k < count; ++k) {
    body(k, z, u.value, v.value);
    z += static_cast<std::uint32_t>(dz);
    u.value += u.step;
    u.step += u.curve;
    v.value += v.step;
    v.step += v.curve;
  }
}

// The pixels of a run from the first whose depth passes `passes(k, z)` (a pass's depth
// test without its side effects) to the run's end; empty when none passes. Before it the
// kernel would change nothing, so the small path hands it only these, and sets up no uv
// for a triangle whose rows are all hidden (the back of a model drawn without culling:
// mesh_bear -2 % on M7, -5 % on M0+). Only the front is trimmed: a scan from the back
// cost more on the runs it left whole than it saved (M7 +0.8 %).
template <typename Test>
[[gnu::always_inline]] inline PixelRange passing_range(std::int32_t count, std::uint32_t z, std::int32_t dz, Test&& passes) {
  std::int32_t first = 0;
  for (; first < count; ++first, z += static_cast<std::uint32_t>(dz))
    if (passes(first, z)) return {first, count};
  return {0, 0};
}
// The ranges of the two depth tests, run pixel k at depth[k]: nearer than the stored depth
// (the fused pass), or equal to it (modulate; without the tie mask's claim).
template <typename DepthT, typename Format>
[[gnu::always_inline]] inline PixelRange nearer_range(const DepthT* depth, const Format& f, std::int32_t count, std::uint32_t z, std::int32_t dz) {
  return passing_range(count, z, dz, [depth, &f](std::int32_t k, std::uint32_t zk) SPANLIGHT_LAMBDA_INLINE_ATTR { return f.store(zk) < depth[k]; });
}
template <typename DepthT, typename Format>
[[gnu::always_inline]] inline PixelRange equal_range(const DepthT* depth, const Format& f, std::int32_t count, std::uint32_t z, std::int32_t dz) {
  return passing_range(count, z, dz, [depth, &f](std::int32_t k, std::uint32_t zk) SPANLIGHT_LAMBDA_INLINE_ATTR {
    return z_equal(depth, f, static_cast<std::uint32_t>(k), zk);
  });
}

[[gnu::always_inline]] inline void step(Stepped& x) {
  x.value += x.step;
  x.step += x.curve;
}

template <Features F, typename DepthT, typename Hooks>
struct ShadowDepthKernel {
  static constexpr bool may_need_uv = false, may_need_projectors = false;
  DepthT* map;
  DepthFormat<F.depth_bits> depth;
  Hooks& hooks;
  SpanNeeds object(const ObjectData&) { return {false, {}, 0, 0}; }
  template <int P>
  void run(std::uint32_t i, std::int32_t count, const PixelRun<P>& r) const {
    DepthT* d = map + i;
    for_each_pixel(count, r.z, r.dz, [&](std::int32_t k, std::uint32_t z) SPANLIGHT_LAMBDA_INLINE_ATTR {
      const std::uint32_t stored = depth.store(z);
      if (stored < d[k]) {
        d[k] = static_cast<DepthT>(stored);
        hooks.touched(Pass::shadow_depth, i + static_cast<std::uint32_t>(k));
      }
    });
  }
};

template <Features F, typename DepthT, typename Hooks>
struct DepthAmbientKernel {
  using Color = ColorTraits<F.format>;
  static constexpr bool may_need_uv = false, may_need_projectors = false;
  BandBuffers<F.format, DepthT> band;
  Colour ambient;  // quantised to the format
  DepthFormat<F.depth_bits> depth;
  Hooks& hooks;
  SpanNeeds object(const ObjectData&) { return {false, {}, 0, 0}; }
  template <int P>
  void run(std::uint32_t i, std::int32_t count, const PixelRun<P>& r) const {
    typename Color::Storage stored_ambient[Color::per_pixel];
    Color::store(stored_ambient, ambient);
    DepthT* d = band.depth + i;
    typename Color::Storage* c = band.color + i * Color::per_pixel;
    for_each_pixel(count, r.z, r.dz, [&](std::int32_t k, std::uint32_t z) SPANLIGHT_LAMBDA_INLINE_ATTR {
      const std::uint32_t stored = depth.store(z);
      if (stored < d[k]) {
        d[k] = static_cast<DepthT>(stored);
        for (int b = 0; b < Color::per_pixel; ++b) c[k * Color::per_pixel + b] = stored_ambient[b];
        hooks.touched(Pass::depth_ambient, i + static_cast<std::uint32_t>(k));
      }
    });
  }
};

// The value a stepped value reaches after n pixels.
[[gnu::always_inline]] constexpr std::int32_t after(const Stepped& x, std::uint32_t n) {
  return static_cast<std::int32_t>(x.value + n * x.step + (n * (n - 1) / 2) * x.curve);
}

// Whether a projector can light some pixel of a run: q > 0, and not outside
// the frustum at both ends on one side (each ratio is monotonic along the row).
template <int P>
[[gnu::always_inline]] inline bool may_light(const PixelRun<P>& r, int j, std::int32_t count) {
  if (!r.front[j]) return false;
  const auto last = static_cast<std::uint32_t>(count - 1);
  auto outside = [&](const Stepped& x) SPANLIGHT_LAMBDA_INLINE_ATTR {
    const auto a = static_cast<std::int32_t>(x.value), b = after(x, last);
    return (a < 0 && b < 0) || (a > proj_one && b > proj_one);
  };
  return !(outside(r.s[j]) || outside(r.t[j]) || outside(r.r[j]));
}

// A projector's stepped (s, t, r) at the current pixel.
struct ProjectorValues {
  Stepped s, t, r;
  [[gnu::always_inline]] void next() {
    step(s);
    step(t);
    step(r);
  }
  [[gnu::always_inline]] bool inside() const { return in_frustum(s_now(), t_now(), r_now()); }
  [[gnu::always_inline]] std::int32_t s_now() const { return static_cast<std::int32_t>(s.value); }
  [[gnu::always_inline]] std::int32_t t_now() const { return static_cast<std::int32_t>(t.value); }
  [[gnu::always_inline]] std::int32_t r_now() const { return static_cast<std::int32_t>(r.value); }
};

template <Features F, typename DepthT, typename Hooks>
struct LightKernel {
  using Color = ColorTraits<F.format>;
  static constexpr bool may_need_uv = false, may_need_projectors = true;
  BandBuffers<F.format, DepthT> band;
  Light<DepthT> light;
  int projector;
  DepthFormat<F.depth_bits> depth;
  Hooks& hooks;
  SpanNeeds object(const ObjectData&) { return {false, {}, projector, projector + 1}; }
  template <int P>
  void run(std::uint32_t i, std::int32_t count, const PixelRun<P>& r) const {
    const int j = projector;
    const bool lights = may_light(r, j, count);
    ProjectorValues p{r.s[j], r.t[j], r.r[j]};
    for_each_pixel(count, r.z, r.dz, [&](std::int32_t k, std::uint32_t z) SPANLIGHT_LAMBDA_INLINE_ATTR {
      const std::uint32_t pixel = i + static_cast<std::uint32_t>(k);
      if (z_equal_and_first(band.depth, band.tie_mask, depth, pixel, z)) {
        hooks.touched(Pass::light, pixel);
        if (lights && p.inside()) {
          const Colour add = projector_light<F>(light, p.s_now(), p.t_now(), p.r_now(), 32 - depth.shift);
          if (!is_black(add)) {
            typename Color::Storage* c = band.color + pixel * Color::per_pixel;
            Color::store(c, add_light(Color::load(c), add));
          }
        }
      }
      p.next();
    });
  }
};

template <Features F, typename DepthT, typename Hooks>
struct ModulateKernel {
  using Color = ColorTraits<F.format>;
  static constexpr bool may_need_uv = true, may_need_projectors = false;
  BandBuffers<F.format, DepthT> band;
  const TextureData* textures;
  DepthFormat<F.depth_bits> depth;
  Hooks& hooks;
  Surface surface{};
  SpanNeeds object(const ObjectData& o) {
    surface = surface_of(o, textures);
    return {o.texture >= 0, surface.scale, 0, 0, surface.kind == SurfaceKind::trilinear};
  }
  PixelRange passing(std::uint32_t i, std::int32_t count, std::uint32_t z, std::int32_t dz) const {
    return equal_range(band.depth + i, depth, count, z, dz);
  }
  template <int P>
  void run(std::uint32_t i, std::int32_t count, const PixelRun<P>& r) const {
    with_sampler<F>(surface, r.level, [&](auto&& sample) SPANLIGHT_LAMBDA_INLINE_ATTR {
      for_each_pixel(count, r.z, r.dz, r.u, r.v, [&](std::int32_t k, std::uint32_t z, std::uint32_t u, std::uint32_t v) SPANLIGHT_LAMBDA_INLINE_ATTR {
        const std::uint32_t pixel = i + static_cast<std::uint32_t>(k);
        if (z_equal_and_first(band.depth, band.tie_mask, depth, pixel, z)) {
          hooks.touched(Pass::modulate, pixel);
          typename Color::Storage* c = band.color + pixel * Color::per_pixel;
          Color::store(c, modulate(Color::load(c), sample(u, v, k)));
        }
      });
    });
  }
};

// Everything at once, with the multipass's quantisation steps: the light is
// quantised to the format after the ambient and after each projector's add.
template <Features F, typename DepthT, typename Hooks>
struct FusedKernel {
  using Color = ColorTraits<F.format>;
  static constexpr int P = F.max_projectors;
  static constexpr bool may_need_uv = true, may_need_projectors = P > 0;
  BandBuffers<F.format, DepthT> band;
  const TextureData* textures;
  const Light<DepthT>* lights;  // one per projector
  int projector_count;
  Colour ambient;  // quantised to the format
  DepthFormat<F.depth_bits> depth;
  Hooks& hooks;
  Surface surface{};
#if defined(__ARM_ARCH_6M__)
  Thumb1Object thumb1{};  // the object as the Thumb-1 run reads it (thumb1_shape)
#endif
  SpanNeeds object(const ObjectData& o) {
    surface = surface_of(o, textures);
#if defined(__ARM_ARCH_6M__)
    if constexpr (thumb1_shape) set_thumb1_object();
#endif
    return {o.texture >= 0, surface.scale, 0, projector_count, surface.kind == SurfaceKind::trilinear};
  }
  PixelRange passing(std::uint32_t i, std::int32_t count, std::uint32_t z, std::int32_t dz) const {
    return nearer_range(band.depth + i, depth, count, z, dz);
  }
  // Whether every pixel of the box (columns x rows from pixel i, rows `stride` apart) already holds a
  // depth this pass would not replace with z or anything farther: a triangle nearest at z draws nothing there.
  bool hides(std::uint32_t i, std::int32_t columns, std::int32_t rows, std::int32_t stride, std::uint32_t z) const {
    const auto s = depth.store(z);
    for (std::int32_t r = 0; r < rows; ++r, i += static_cast<std::uint32_t>(stride))
      for (std::int32_t c = 0; c < columns; ++c)
        if (s < band.depth[i + static_cast<std::uint32_t>(c)]) return false;
    return true;
  }

  template <int PR>
  void run(std::uint32_t i, std::int32_t count, const PixelRun<PR>& r) const {
    bool any_light = false;
    for_each_projector<P>(0, projector_count, [&](int j) SPANLIGHT_LAMBDA_INLINE_ATTR { any_light |= may_light(r, j, count); });
#if defined(__ARM_ARCH_6M__)
    if constexpr (thumb1_shape) {
      if (!any_light && !(F.tinted && surface.tinted)) {
        if constexpr (F.bilinear) {
          if (surface.kind == SurfaceKind::bilinear_repeat) return thumb1_run<true>(i, count, r);
        }
        if constexpr (F.nearest) {
          if (surface.kind == SurfaceKind::nearest_repeat) return thumb1_run<false>(i, count, r);
        }
      }
    }
#endif
    with_sampler<F>(surface, r.level, [&](auto&& sample) SPANLIGHT_LAMBDA_INLINE_ATTR {
      if (!any_light) constant_light(i, count, r, sample);
      else lit(i, count, r, sample);
    });
  }

 private:
#if defined(__ARM_ARCH_6M__)
  // The shapes thumb1_run.hpp draws: 16- or 24-bit depth in halfwords or words, RGB565 or
  // RGB888, nothing watching the pixels.
  static constexpr bool thumb1_shape =
      (F.format == PixelFormat::rgb565 || F.format == PixelFormat::rgb888) && !sees_pixels<Hooks>() &&
      ((F.depth_bits == 16 && std::is_same_v<DepthT, std::uint16_t>) || (F.depth_bits == 24 && std::is_same_v<DepthT, std::uint32_t>));

  // The object's and the pass's words for the Thumb-1 run.
  void set_thumb1_object() {
    const TexelGrid& g = surface.grid;
    const int down = surface.kind == SurfaceKind::bilinear_repeat ? 8 : 0;  // bilinear: the index and the weight
    auto colour = reinterpret_cast<std::uintptr_t>(band.color);
    if constexpr (F.depth_bits == 16 && F.format == PixelFormat::rgb565) colour -= reinterpret_cast<std::uintptr_t>(band.depth);
    thumb1 = {colour, reinterpret_cast<std::uintptr_t>(band.depth), g.texels, g.stride, static_cast<std::uint32_t>(g.x_shift - down),
              static_cast<std::uint32_t>(g.y_shift - down), red(ambient), blue(ambient), green(ambient), ambient != white};
  }

  // A run of a repeating texture under a constant light, in Thumb-1.
  template <bool Bilinear, int PR>
  void thumb1_run(std::uint32_t i, std::int32_t count, const PixelRun<PR>& r) const {
    static_assert(offsetof(PixelRun<PR>, z) == 0 && offsetof(PixelRun<PR>, dz) == 4 && offsetof(PixelRun<PR>, u) == 8 &&
                  offsetof(PixelRun<PR>, v) == 20 && sizeof(Stepped) == 12, "the Thumb-1 run reads these words");
    if (count > 0) thumb1_fused_run<F.depth_bits, F.format, Bilinear>(&r, thumb1, band.depth + i, band.depth + i + count);
  }
#endif

  // No projector reaches the run: the light is the ambient all along.
  template <int PR, typename Sample>
  [[gnu::always_inline]] void constant_light(std::uint32_t i, std::int32_t count, const PixelRun<PR>& r, Sample& sample) const {
    const Colour light = ambient;
    DepthT* d = band.depth + i;
    typename Color::Storage* c = band.color + i * Color::per_pixel;
    auto pixels = [&](auto shade) SPANLIGHT_LAMBDA_INLINE_ATTR {
      for_each_pixel(count, r.z, r.dz, r.u, r.v, [&](std::int32_t k, std::uint32_t z, std::uint32_t u, std::uint32_t v) SPANLIGHT_LAMBDA_INLINE_ATTR {
        const std::uint32_t stored = depth.store(z);
        if (stored < d[k]) {
          d[k] = static_cast<DepthT>(stored);
          hooks.touched(Pass::fused, i + static_cast<std::uint32_t>(k));
          Color::store(c + k * Color::per_pixel, shade(sample(u, v, k)));
        }
      });
    };
    if (light == white) pixels([](Colour s) SPANLIGHT_LAMBDA_INLINE_ATTR { return s; });  // modulate by white: the surface
    else pixels([light](Colour s) SPANLIGHT_LAMBDA_INLINE_ATTR { return modulate(light, s); });
  }

  template <int PR, typename Sample>
  [[gnu::always_inline]] void lit(std::uint32_t i, std::int32_t count, const PixelRun<PR>& r, Sample& sample) const {
    DepthT* d = band.depth + i;
    typename Color::Storage* c = band.color + i * Color::per_pixel;
    ProjectorValues p[projector_slots(P)] = {};
    bool on[projector_slots(P)] = {};
    for_each_projector<P>(0, projector_count, [&](int j) SPANLIGHT_LAMBDA_INLINE_ATTR {
      p[j] = {r.s[j], r.t[j], r.r[j]};
      on[j] = may_light(r, j, count);
    });
    for_each_pixel(count, r.z, r.dz, r.u, r.v, [&](std::int32_t k, std::uint32_t z, std::uint32_t u, std::uint32_t v) SPANLIGHT_LAMBDA_INLINE_ATTR {
      const std::uint32_t stored = depth.store(z);
      if (stored < d[k]) {
        d[k] = static_cast<DepthT>(stored);
        hooks.touched(Pass::fused, i + static_cast<std::uint32_t>(k));
        Colour light = ambient;
        for_each_projector<P>(0, projector_count, [&](int j) SPANLIGHT_LAMBDA_INLINE_ATTR {
          if (on[j] && p[j].inside()) {
            const Colour add = projector_light<F>(lights[j], p[j].s_now(), p[j].t_now(), p[j].r_now(), 32 - depth.shift);
            if (!is_black(add)) light = Color::quantize(add_light(light, add));
          }
        });
        Color::store(c + k * Color::per_pixel, modulate(light, sample(u, v, k)));
      }
      // A projector off for the whole run is never read again: not stepped either (three_projectors
      // -1.5 % on M7). lit() runs only when one is on, so a lone projector needs no test.
      for_each_projector<P>(0, projector_count, [&](int j) SPANLIGHT_LAMBDA_INLINE_ATTR {
        if (P == 1 || on[j]) p[j].next();
      });
    });
  }
};

}  // namespace spanlight
