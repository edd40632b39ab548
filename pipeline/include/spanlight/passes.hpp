// The per-pass kernels the geometry walk calls at each covered pixel. Each is
// tiny and inlined into the span loop, so a pass pays only for what it reads.
#pragma once

#include <cstdint>

#include "spanlight/buffers.hpp"
#include "spanlight/geometry.hpp"
#include "spanlight/shade.hpp"

namespace spanlight {

// Observers let tests see which pixels a pass touched; firmware uses none.
struct NoObserver {
  static constexpr void touched(int /*pass*/, std::int32_t /*index*/) {}
};

enum PassId : int { pass_shadow = 0, pass_depth_ambient = 1, pass_light = 2, pass_modulate = 3, pass_fused = 4 };

template <typename DepthT>
struct ShadowDepthKernel {
  static constexpr bool may_need_uv = false, may_need_projectors = false;
  DepthT* map;
  DepthFormat depth;
  SpanNeeds needs() const { return {false, 0, 0}; }
  void object(const ObjectData&) {}
  template <typename V>
  SPANLIGHT_PIXEL_INLINE void pixel(std::int32_t i, const V& v) const {
    const std::uint32_t d = depth.store(v.z);
    if (d < map[i]) map[i] = static_cast<DepthT>(d);
  }
};

template <typename F, typename DepthT, typename Observer>
struct DepthAmbientKernel {
  using Color = ColorTraits<F::format>;
  static constexpr bool may_need_uv = false, may_need_projectors = false;
  FrameTarget<F::format, DepthT> target;
  Rgb8 ambient;
  DepthFormat depth;
  typename Color::Storage stored_ambient[Color::per_pixel] = {};  // packed once, copied per pixel
  SpanNeeds needs() const { return {false, 0, 0}; }
  void object(const ObjectData&) { Color::store(stored_ambient, ambient); }
  template <typename V>
  SPANLIGHT_PIXEL_INLINE void pixel(std::int32_t i, const V& v) const {
    const std::uint32_t d = depth.store(v.z);
    if (d < target.depth[i]) {
      target.depth[i] = static_cast<DepthT>(d);
      for (int k = 0; k < Color::per_pixel; ++k) target.color[i * Color::per_pixel + k] = stored_ambient[k];
      Observer::touched(pass_depth_ambient, i);
    }
  }
  template <int P>
  std::int64_t run(std::int32_t i, std::int32_t count, const PixelRun<P>& r) const {
    return for_each_run_pixel(r, count, [&](std::int32_t k, const PointValues<P>& v) SPANLIGHT_LAMBDA_INLINE { pixel(i + k, v); });
  }
};

// The z-equal test of the light and modulate passes: the depth this triangle
// stores here is the one the depth pass kept, and no other surface with the
// same depth claimed the pixel first.
template <typename Target>
SPANLIGHT_PIXEL_INLINE bool z_equal_and_first(const Target& target, const DepthFormat& depth, std::int32_t i, std::int32_t z) {
  const std::uint32_t d = depth.store(z);
  return d != depth.clear && d == target.depth[i] && claim_pixel(target.tie_mask, i);
}

template <typename F, typename DepthT, typename Observer>
struct LightKernel {
  using Color = ColorTraits<F::format>;
  static constexpr bool may_need_uv = false, may_need_projectors = true;
  FrameTarget<F::format, DepthT> target;
  LightContext light;
  int projector;
  DepthFormat depth;
  SpanNeeds needs() const { return {false, projector, projector + 1}; }
  void object(const ObjectData&) {}
  template <typename V>
  SPANLIGHT_PIXEL_INLINE void pixel(std::int32_t i, const V& v) const {
    if (!z_equal_and_first(target, depth, i, v.z)) return;
    Observer::touched(pass_light, i);
    const Rgb8 add = projector_light<F, DepthT>(light, v, projector, depth.bits);
    if ((add.r | add.g | add.b) == 0) return;
    typename Color::Storage* p = target.color + i * Color::per_pixel;
    Color::store(p, add_light(Color::load(p), add));
  }
  template <int P>
  std::int64_t run(std::int32_t i, std::int32_t count, const PixelRun<P>& r) const {
    if (!r.first.front[projector]) {  // behind the projector all run long (q/w is linear): claims only
      return for_each_run_pixel(r, count, [&](std::int32_t k, const PointValues<P>& v) SPANLIGHT_LAMBDA_INLINE {
        if (z_equal_and_first(target, depth, i + k, v.z)) Observer::touched(pass_light, i + k);
      });
    }
    return for_each_run_pixel(r, count, [&](std::int32_t k, const PointValues<P>& v) SPANLIGHT_LAMBDA_INLINE { pixel(i + k, v); });
  }
};

template <typename F, typename DepthT, typename Observer>
struct ModulateKernel {
  using Color = ColorTraits<F::format>;
  static constexpr bool may_need_uv = true, may_need_projectors = false;
  FrameTarget<F::format, DepthT> target;
  const TextureData* textures;
  const ObjectData* current = nullptr;
  const TextureData* texture = nullptr;
  DepthFormat depth;
  SpanNeeds needs() const { return {current->texture >= 0, 0, 0}; }
  void object(const ObjectData& o) {
    current = &o;
    texture = o.texture >= 0 ? &textures[o.texture] : nullptr;
  }
  template <typename V>
  SPANLIGHT_PIXEL_INLINE void pixel(std::int32_t i, const V& v) const {
    modulate_with(i, v, [&](const V& at) SPANLIGHT_LAMBDA_INLINE { return surface_colour<F>(*current, texture, at); });
  }
  // The object's choices (texture or colour, filter, wrap) made once per run.
  template <int P>
  std::int64_t run(std::int32_t i, std::int32_t count, const PixelRun<P>& r) const {
    return with_run_surface<F, P>(*current, texture, [&](auto&& surface) SPANLIGHT_LAMBDA_INLINE {
      return for_each_run_pixel(r, count, [&](std::int32_t k, const PointValues<P>& v) SPANLIGHT_LAMBDA_INLINE { modulate_with(i + k, v, surface); });
    });
  }

 private:
  template <typename V, typename Surface>
  SPANLIGHT_PIXEL_INLINE void modulate_with(std::int32_t i, const V& v, Surface&& surface) const {
    if (!z_equal_and_first(target, depth, i, v.z)) return;
    Observer::touched(pass_modulate, i);
    typename Color::Storage* p = target.color + i * Color::per_pixel;
    Color::store(p, modulate(Color::load(p), surface(v)));
  }
};

// Everything at once; the same quantisation steps as the passes, so the same bytes.
template <typename F, typename DepthT, typename Observer>
struct FusedKernel {
  using Color = ColorTraits<F::format>;
  static constexpr bool may_need_uv = true, may_need_projectors = true;
  FrameTarget<F::format, DepthT> target;
  const PreparedScene* scene;
  const LightContext* lights;  // one per projector
  Rgb8 ambient;
  const ObjectData* current = nullptr;
  const TextureData* texture = nullptr;
  DepthFormat depth;
  SpanNeeds needs() const { return {current->texture >= 0, 0, scene->projector_count}; }
  void object(const ObjectData& o) {
    current = &o;
    texture = o.texture >= 0 ? &scene->textures[o.texture] : nullptr;
  }
  template <typename V>
  SPANLIGHT_PIXEL_INLINE void pixel(std::int32_t i, const V& v) const {
    fused_with(i, v, [&](const V& at) SPANLIGHT_LAMBDA_INLINE { return surface_colour<F>(*current, texture, at); });
  }
  template <int P>
  std::int64_t run(std::int32_t i, std::int32_t count, const PixelRun<P>& r) const {
    return with_run_surface<F, P>(*current, texture, [&](auto&& surface) SPANLIGHT_LAMBDA_INLINE {
      return for_each_run_pixel(r, count, [&](std::int32_t k, const PointValues<P>& v) SPANLIGHT_LAMBDA_INLINE { fused_with(i + k, v, surface); });
    });
  }

 private:
  template <typename V, typename Surface>
  SPANLIGHT_PIXEL_INLINE void fused_with(std::int32_t i, const V& v, Surface&& surface) const {
    const std::uint32_t d = depth.store(v.z);
    if (d >= target.depth[i]) return;
    target.depth[i] = static_cast<DepthT>(d);
    Observer::touched(pass_fused, i);
    Rgb8 c = Color::quantize(ambient);
    for_each_projector<F::max_projectors>(0, scene->projector_count, [&](int j) SPANLIGHT_LAMBDA_INLINE {
      const Rgb8 add = projector_light<F, DepthT>(lights[j], v, j, depth.bits);
      if ((add.r | add.g | add.b) != 0) c = Color::quantize(add_light(c, add));
    });
    Color::store(target.color + i * Color::per_pixel, modulate(c, surface(v)));
  }
};

}  // namespace spanlight
