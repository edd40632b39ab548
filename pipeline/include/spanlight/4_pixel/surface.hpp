// Stage 4d, the surface colour of an object at a pixel: object colour times its
// texture at (u, v), chosen once per object, so a run's loop calls one sampler
// and the choices a scene does not make are not compiled (Features).
#pragma once

#include <cstdint>
#include <type_traits>
#include <utility>

#include "spanlight/3_span/walk.hpp"
#include "spanlight/4_pixel/colour.hpp"
#include "spanlight/4_pixel/mipmap.hpp"
#include "spanlight/4_pixel/texture.hpp"
#include "spanlight/features.hpp"
#include "spanlight/inline.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

enum class SurfaceKind : std::uint8_t { colour, nearest_repeat, nearest_clamp, nearest_border, bilinear_repeat,
                                        bilinear_clamp, bilinear_border, trilinear };

// A texture with more than one level and the trilinear filter (a 1x1 one is bilinear).
constexpr bool mipmapped(const TextureData& t) { return t.filter == Filter::trilinear && t.level_count > 1; }

struct Surface {
  SurfaceKind kind;
  bool tinted;      // the object's colour is not white: the texel is multiplied by it
  Colour colour;    // the object's colour
  TexelGrid grid;
  StepScale scale;  // how the walk steps uv for this sampler
  const TextureData* texture;  // for trilinear: its levels
  std::uint8_t repeat_size;    // a repeating level 0's (log2 width << 4) | log2 height, as Features::repeat_sizes has it
};

constexpr Surface surface_of(const ObjectData& o, const TextureData* textures) {
  Surface s{};
  s.colour = colour_of(o.color[0], o.color[1], o.color[2]);
  s.tinted = s.colour != white;
  if (o.texture < 0) {
    s.kind = SurfaceKind::colour;
    return s;
  }
  const TextureData& t = textures[o.texture];
  const int f = o.uv_frac_bits;
  s.grid = texel_grid(t.levels[0], f);
  const int wrap = t.wrap == Wrap::repeat ? 0 : (t.wrap == Wrap::clamp ? 1 : 2);
  const bool bilinear = t.filter != Filter::nearest;
  s.kind = mipmapped(t) ? SurfaceKind::trilinear : static_cast<SurfaceKind>((bilinear ? 4 : 1) + wrap);
  s.texture = &t;
  // Bilinear reads the texels around the point half a texel back (centres at half-integers).
  const std::int32_t back = bilinear ? -(std::int32_t{1} << (f - 1)) : 0;
  if (t.wrap == Wrap::repeat) {  // a fraction of the size in 32 bits: x_shift = 32 - log2 width >= f
    s.repeat_size = static_cast<std::uint8_t>(((32 - s.grid.x_shift) << 4) | (32 - s.grid.y_shift));
    s.scale = {{back, back, 0},
               {static_cast<std::uint8_t>(s.grid.x_shift - f), static_cast<std::uint8_t>(s.grid.y_shift - f), 0},
               static_cast<std::uint8_t>(s.grid.x_shift < s.grid.y_shift ? s.grid.x_shift : s.grid.y_shift)};
  } else {
    s.scale = {{back, back, 0}, {0, 0, 0}, static_cast<std::uint8_t>(f)};
  }
  return s;
}

// Calls fn(Sampler<log2 w, log2 h>{texels}) when the grid's size (Surface::repeat_size, worked
// out once an object) is one of F.repeat_sizes, and says whether it did.
template <Features F, template <int, int> class Sampler, typename Fn>
[[gnu::always_inline]] inline bool with_size(const TexelGrid& g, std::uint8_t size, Fn&& fn) {
  bool done = false;
  [&]<std::size_t... I>(std::index_sequence<I...>) SPANLIGHT_LAMBDA_INLINE_ATTR {
    (([&]() SPANLIGHT_LAMBDA_INLINE_ATTR {
       constexpr std::uint8_t s = F.repeat_sizes[I];
       if constexpr (s != 0) {
         if (!done && size == s) {
           fn(Sampler<(s >> 4), (s & 15)>{g.texels});
           done = true;
         }
       }
     }()),
     ...);
  }(std::make_index_sequence<4>{});
  return done;
}

// Calls fn(sample) with sample(x, y, i) -> Colour, the surface's sampler of
// stepped coordinates at the run's pixel i (`level`: the run's mip levels,
// trilinear only), instantiated only for the kinds features F allows.
template <Features F, typename Fn>
[[gnu::always_inline]] inline void with_sampler(const Surface& s, const RunLevel& level, Fn&& fn) {
  const TexelGrid g = s.grid;  // by value: the run loop keeps it in registers
  auto sampled = [&](auto&& sample) SPANLIGHT_LAMBDA_INLINE_ATTR {
    using Sample = std::remove_cvref_t<decltype(sample)>;
    auto at_pixel = [&sample](std::uint32_t x, std::uint32_t y, std::int32_t i) SPANLIGHT_LAMBDA_INLINE_ATTR {
      if constexpr (std::is_invocable_v<const Sample&, std::uint32_t, std::uint32_t, std::int32_t>) return sample(x, y, i);
      else return sample(x, y);
    };
    if constexpr (F.tinted) {
      if (s.tinted) {
        const Colour colour = s.colour;
        return fn([&at_pixel, colour](std::uint32_t x, std::uint32_t y, std::int32_t i) SPANLIGHT_LAMBDA_INLINE_ATTR { return modulate(colour, at_pixel(x, y, i)); });
      }
    }
    fn(at_pixel);
  };
  auto as_signed = [](std::uint32_t x) SPANLIGHT_LAMBDA_INLINE_ATTR { return static_cast<std::int32_t>(x); };
  switch (s.kind) {
    case SurfaceKind::colour: {
      const Colour c = s.colour;
      return fn([c](std::uint32_t, std::uint32_t, std::int32_t) SPANLIGHT_LAMBDA_INLINE_ATTR { return c; });
    }
    case SurfaceKind::bilinear_repeat:
      if constexpr (F.bilinear) {
        if (with_size<F, BilinearRepeatOfSize>(g, s.repeat_size, sampled)) return;
        if constexpr (F.any_repeat_size) return sampled([g](std::uint32_t x, std::uint32_t y) SPANLIGHT_LAMBDA_INLINE_ATTR { return bilinear_repeat(g, x, y); });
      }
      break;
    case SurfaceKind::bilinear_clamp:
      if constexpr (F.bilinear && F.clamped) return sampled([g, as_signed](std::uint32_t x, std::uint32_t y) SPANLIGHT_LAMBDA_INLINE_ATTR { return bilinear_clamp(g, as_signed(x), as_signed(y)); });
      break;
    case SurfaceKind::bilinear_border:
      if constexpr (F.bilinear && F.clamped) return sampled([g, as_signed](std::uint32_t x, std::uint32_t y) SPANLIGHT_LAMBDA_INLINE_ATTR { return bilinear_border(g, as_signed(x), as_signed(y)); });
      break;
    case SurfaceKind::nearest_repeat:
      if constexpr (F.nearest) {
        if (with_size<F, NearestRepeatOfSize>(g, s.repeat_size, sampled)) return;
        if constexpr (F.any_repeat_size) return sampled([g](std::uint32_t x, std::uint32_t y) SPANLIGHT_LAMBDA_INLINE_ATTR { return nearest_repeat(g, x, y); });
      }
      break;
    case SurfaceKind::nearest_clamp:
      if constexpr (F.nearest && F.clamped) return sampled([g, as_signed](std::uint32_t x, std::uint32_t y) SPANLIGHT_LAMBDA_INLINE_ATTR { return nearest<Wrap::clamp>(g, as_signed(x), as_signed(y)); });
      break;
    case SurfaceKind::nearest_border:
      if constexpr (F.nearest && F.clamped) return sampled([g, as_signed](std::uint32_t x, std::uint32_t y) SPANLIGHT_LAMBDA_INLINE_ATTR { return nearest<Wrap::border>(g, as_signed(x), as_signed(y)); });
      break;
    case SurfaceKind::trilinear:
      if constexpr (F.trilinear) {
        if (s.texture->wrap == Wrap::repeat) return with_run_levels<Wrap::repeat>(*s.texture, g, level, sampled);
        if constexpr (F.clamped) {
          if (s.texture->wrap == Wrap::clamp) return with_run_levels<Wrap::clamp>(*s.texture, g, level, sampled);
          return with_run_levels<Wrap::border>(*s.texture, g, level, sampled);
        }
      }
      break;
  }
}

}  // namespace spanlight
