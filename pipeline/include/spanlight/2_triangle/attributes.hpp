// Stage 2b, a triangle's attributes at its three vertices, as the span stage
// interpolates them: uv relative to vertex 0, and each projector's (s, t, r, q)
// scaled together so that the largest fits 30 bits (only the ratios s/q, t/q,
// r/q matter).
#pragma once

#include <algorithm>
#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "spanlight/1_vertex/clip.hpp"
#include "spanlight/features.hpp"

namespace spanlight {

inline constexpr int proj_frac_bits = 28;             // s/q, t/q, r/q in Q3.28
inline constexpr std::int32_t proj_limit = 1 << 30;   // saturate at +-4: far outside [0, 1]
inline constexpr std::int32_t one_q30 = 1 << 30;

template <int P>
struct TriangleAttributes {
  std::int32_t u0, du1, du2, v0, dv1, dv2;  // texel coordinates * 2^uv_frac_bits (|u| < 2^29)
  // per projector: (s, t, r, q) at vertex 0 and the deltas, normalised so |value| < 2^30
  [[no_unique_address]] PerProjector<std::int32_t[4], P> proj0, proj_d1, proj_d2;
};

// The attributes of the triangle whose vertices `v` are, in setup order.
template <int P>
constexpr void set_uv(const ClipVertex<P>* const (&v)[3], TriangleAttributes<P>& a) {
  a.u0 = v[0]->u;
  a.du1 = v[1]->u - a.u0;
  a.du2 = v[2]->u - a.u0;
  a.v0 = v[0]->v;
  a.dv1 = v[1]->v - a.v0;
  a.dv2 = v[2]->v - a.v0;
}

template <int P>
constexpr void set_projector(const ClipVertex<P>* const (&v)[3], int j, TriangleAttributes<P>& a) {
  std::uint64_t largest = 0;
  for (const ClipVertex<P>* cv : v) {
    const std::int64_t comps[4] = {cv->proj[j].x, cv->proj[j].y, cv->proj[j].z, cv->proj[j].w};
    for (std::int64_t c : comps) {
      const std::uint64_t m = static_cast<std::uint64_t>(c < 0 ? -c : c);
      if (m > largest) largest = m;
    }
  }
  // One shift for all twelve values keeps their ratios.
  const int shift = std::max(fixedpoint::bit_length(largest) - 30, 0);
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

// A projector that lights nothing of this triangle (it faces away, facing_only):
// q = -1 all over, so every pixel is behind the projector and only claimed.
template <int P>
constexpr void set_unlit(int j, TriangleAttributes<P>& a) {
  for (int c = 0; c < 4; ++c) a.proj0[j][c] = a.proj_d1[j][c] = a.proj_d2[j][c] = 0;
  a.proj0[j][3] = -1;
}

}  // namespace spanlight
