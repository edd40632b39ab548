// What a scene uses, known at compile time, so that what it does not use is
// not compiled (tgx's idea). `spanlight bake` writes one Features value per
// scene; the host tools instantiate the pipeline with everything on.
//
//   render_frame<baked::features>(...)          // firmware: only the scene's code
//   render_frame<host_features(format)>(...)    // host: every feature, knobs at run time
//
// A Features value is a template argument (a C++20 class-type parameter), so
// every field reads by name at its point of use: `if constexpr (F.shadows)`.
#pragma once

#include <cstddef>
#include <cstdint>

#include "spanlight/knobs.hpp"

namespace spanlight {

struct Features {
  std::uint8_t max_projectors = 4;  // 0 links no projector code at all
  bool shadows = true;              // shadow maps and the depth compare
  bool pcf = true;                  // the pcf2x2 shadow filter (else nearest only)
  bool nearest = true;              // some texture is sampled nearest
  bool bilinear = true;             // some texture (or projector image) is sampled bilinearly
  bool clamped = true;              // some object texture wraps with clamp or border (else repeat only)
  bool tinted = true;               // some textured object has a colour other than white
  bool trilinear = true;            // some object texture is mipmapped (scene format 2)
  bool falloff = true;              // some projector's light falls off with its depth (scene format 2)
  bool facing = true;               // some projector lights only the triangles facing it (scene format 2)
  bool closed_solids = true;        // some object drawn without culling is a closed solid (1_vertex/closed.hpp)
  PixelFormat format = PixelFormat::rgb888;
  bool fused = true;                // the fused pass is linked
  bool multipass = true;            // the paper's passes are linked
  // The reciprocal of the perspective divide: fixed at bake time for firmware;
  // 0 table bits = chosen at run time from Knobs (the host).
  std::uint8_t table_bits = 0;
  std::uint8_t newton = 0;
  // Depth bits fixed at bake time (16 or 24); 0: the knob's, at run time.
  std::uint8_t depth_bits = 0;
  // The sizes of the repeating textures, (log2 width << 4) | log2 height, 0 for an
  // unused slot: their samplers get the size as constants, which frees the
  // registers a run loop needs. any_repeat_size: other sizes may occur too (a
  // sampler with the size in registers is compiled for them).
  std::uint8_t repeat_sizes[4] = {};
  bool any_repeat_size = true;

  friend constexpr bool operator==(const Features&, const Features&) = default;
};

// The host's build: every feature, the reciprocal and the passes as the knobs say.
constexpr Features host_features(PixelFormat format) {
  Features f;
  f.format = format;
  return f;
}

// Whether a build with these features can render with these knobs.
constexpr bool supports(const Features& f, const Knobs& k) {
  if (k.format != f.format) return false;
  if (k.passes == Passes::fused ? !f.fused : !f.multipass) return false;
  if (f.depth_bits != 0 && f.depth_bits != k.depth_bits) return false;
  return f.table_bits == 0 || (f.table_bits == k.table_bits && f.newton == k.newton);
}

// Array slots for up to n projectors (at least one: C++ has no empty arrays).
constexpr std::size_t projector_slots(int n) { return n > 0 ? static_cast<std::size_t>(n) : 1u; }

// One T per projector, as a member of the per-triangle and per-run state: with
// [[no_unique_address]] it takes no bytes at all in a build without projectors
// (P = 0), where an array would keep one unused slot (a clip vertex's is 32
// bytes, and a clipped triangle holds 18 of them). Indexed only for projectors
// j < P: with none, nothing can index it.
template <typename T, int P>
struct PerProjector {
  T slot[static_cast<std::size_t>(P)];
  constexpr T& operator[](int j) { return slot[j]; }
  constexpr const T& operator[](int j) const { return slot[j]; }
};
template <typename T>
struct PerProjector<T, 0> {
  [[noreturn]] T& operator[](int) const { __builtin_unreachable(); }
};

// Calls fn(j) for each projector j in [begin, end). Unrolled over the
// compile-time maximum N, so j is a constant in each copy and a walk's
// per-projector values stay in registers instead of an array indexed at run time.
// The pragma makes the unrolling certain: GCC's own choice kept a two-projector
// kernel's loop (v2_facing_wall on Cortex-M7: 25.6 -> 23.0 M with it).
template <int N, typename Fn>
[[gnu::always_inline]] inline void for_each_projector(int begin, int end, Fn&& fn) {
#pragma GCC unroll 16
  for (int j = 0; j < N; ++j) {
    if (j >= begin && j < end) fn(j);
  }
}

}  // namespace spanlight
