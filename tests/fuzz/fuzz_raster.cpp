// libFuzzer harness: triangle setup (the general int64 one and the small
// triangles' 32-bit one), the row walk and the span walk on arbitrary vertex
// data within the documented input ranges.
//
// Two modes (first byte):
//  screen  three ScreenVertex values as setup takes them: x, y within the
//          guard band's +-(2^21 - 1) subpixels (setup.hpp), z in [0, 2^30],
//          1/w as a mantissa in [2^30, 2^31) and an exponent in [31, 94]
//          (what project.hpp produces);
//  clip    three clip-space vertices within the transform's bound (vec.hpp:
//          prepare keeps matrix entries < 2^13 and positions < 2^14, so a
//          clip component is < 3 * 2^13 * 2^14 + 2^13 units), clipped
//          (clip.hpp) with the guard band of the viewport, projected and fanned
//          as draw_pass does; the snapped vertices must then be within setup's
//          +-2^21 subpixels.
// Viewports are 1..512 pixels a side (1..4096 one time in 16). walk_span runs
// on up to 5 rows of each triangle, spread over it (the first and the last among them).
// Checked for every triangle:
//  - rows come in order, once each, inside the viewport; spans have c0 <= c1
//    inside the viewport;
//  - walk_span hands the kernel runs covering exactly columns c0..c1, in order;
//  - the stepped depth stays within depth_drift_limit of the exact depth at each
//    pixel and never beyond the depth format's z_limit;
//  - the covered pixels are exactly float_model::covered_pixels' on the same
//    snapped vertices (viewports up to 128x128; above that, each span's ends
//    are covered by the rule and the pixels beside them are not), and where
//    setup_small takes the triangle, its rows cover the very same pixels.
// Any violation aborts (a libFuzzer crash).
//  - every clipped vertex is in front of the eye and inside each plane it was
//    clipped against, up to lerp's rounding.
// Environment: SPANLIGHT_FUZZ_VERBOSE=1 prints an input's clip-space polygon
// before and after clipping.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <utility>
#include <vector>

#include "float_model/raster.hpp"
#include "float_model/setup.hpp"
#include "spanlight/4_pixel/depth.hpp"
#include "spanlight/5_frame/draw.hpp"

namespace sl = spanlight;
namespace fm = spanlight::float_model;

namespace {

constexpr int P = 1;
constexpr sl::FixedDivide<8, 1> divide{};

struct Bytes {
  const std::uint8_t* data;
  std::size_t size;
  std::size_t at = 0;
  std::uint64_t next(int bits) {
    std::uint64_t v = 0;
    for (int b = 0; b < bits; b += 8) v = (v << 8) | (at < size ? data[at++] : 0u);
    return bits >= 64 ? v : v & ((std::uint64_t{1} << bits) - 1);
  }
  // A value in [lo, hi], from `bits` bits of input.
  std::int64_t in(std::int64_t lo, std::int64_t hi, int bits) {
    const std::uint64_t span = static_cast<std::uint64_t>(hi - lo) + 1;
    return lo + static_cast<std::int64_t>(span == 0 ? next(bits) : next(bits) % span);
  }
};

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_raster: %s\n", what);
  std::abort();
}

constexpr std::int32_t guard_limit = (1 << 21) - 1;

// How far the stepped depth may drift from the exact depth (Q0.32 units) `k` pixels after the
// span's start, where both are exact: each exact depth is off the truth by 2 * 14 + 1 units
// (lambda_1, lambda_2 within 3.5 * 2^-30 each, times |dz| <= 1, and the product's floor), and
// k steps of dzdx by the floor (1.25 units a step: mul_shift_wide and num >> pre) and by 4/D's
// relative error (reciprocal<8, 2> < 2^-28.9, d_norm's truncation 2^-31, the halving 2^-30)
// over the depth they cover (< 2^32 units): 2^32 * 2^-28.2 < 15 units.
constexpr std::int64_t depth_drift_limit(std::int64_t k) { return 2 * 29 + 1 + (5 * k + 3) / 4 + 15; }
constexpr std::int64_t clip_limit = (3 * (std::int64_t{1} << 27) + (1 << 13)) * (std::int64_t{1} << 32);  // units * 2^32

void check_triangle(const sl::ScreenVertex (&v)[3], const sl::ClipVertex<P>* const (&clip)[3], sl::Cull cull, int width,
                    int height, Bytes& in) {
  for (const sl::ScreenVertex& s : v)
    if (s.x < -guard_limit || s.x > guard_limit || s.y < -guard_limit || s.y > guard_limit) fail("snapped vertex outside the guard band");
  sl::TriangleSetup t{};
  const fm::SnappedVertex tri[3] = {{v[0].x, v[0].y}, {v[1].x, v[1].y}, {v[2].x, v[2].y}};
  const bool full_check = width <= 128 && height <= 128;
  std::vector<std::uint8_t> emitted(full_check ? static_cast<std::size_t>(width * height) : 0, 0);
  const sl::DepthFormat<> depth(24);
  if (sl::setup_triangle(v, cull, height, t)) {
    sl::TriangleAttributes<P> a{};
    const sl::ClipVertex<P>* const ordered[3] = {clip[t.order[0]], clip[t.order[1]], clip[t.order[2]]};
    sl::set_uv<P>(ordered, a);
    sl::set_projector<P>(ordered, 0, a);
    const auto image = static_cast<std::uint16_t>(in.in(1, 4096, 16));
    const std::uint16_t texels[1] = {image};
    // Q3.28 units per texel of the larger side, as draw_pass works it out (which takes clz32(0) for a
    // one-texel image: undefined; here 0 bits of size).
    const int size_bits = image > 1 ? 32 - fixedpoint::clz32(image - 1u) : 0;
    const std::uint8_t texel_bits[1] = {static_cast<std::uint8_t>(sl::proj_frac_bits - size_bits)};
    // uv in texels * 2^frac (8..16), stepped as a clamped texture's (shift 0) or a repeating one's (shifted up).
    const int frac = static_cast<int>(in.in(8, 16, 8));
    const auto up = static_cast<std::uint8_t>(in.in(0, 24 - frac, 8));
    const sl::StepScale uv_scale{{0, 0, 0}, {up, up, 0}, static_cast<std::uint8_t>(frac + up)};
    const sl::SpanControl control{static_cast<int>(in.in(0, 6, 8)), static_cast<int>(in.in(0, 10, 8)), &uv_scale, frac,
                                  texels, texel_bits, depth.z_limit};
    const sl::SpanNeeds needs{true, uv_scale, 0, 1};
    // walk_span on at most 4 rows spread over the triangle (it is the slow part).
    const std::int32_t rows = t.row_end - t.row_begin, stride = rows > 4 ? rows / 4 : 1;
    std::int32_t last_row = -1;
    sl::PixelRun<P> pixel_run{};  // zeroed once a triangle, as draw.hpp does
    sl::rasterize_rows(t, width, [&](std::int32_t row, std::int32_t c0, std::int32_t c1) {
      if (row <= last_row || row < 0 || row >= height) fail("row out of order or outside the viewport");
      if (c0 > c1 || c0 < 0 || c1 >= width) fail("span outside the viewport");
      last_row = row;
      const bool walk = (row - t.row_begin) % stride == 0 || row + 1 == t.row_end;
      if (walk) {
        std::int32_t expect = c0;
        sl::walk_span<P, true, true>(t, a, needs, control, divide, c0, c1, pixel_run,
                                     [&](std::int32_t column, std::int32_t count, const sl::PixelRun<P>& run) {
          if (column != expect || count < 1) fail("walk_span skipped or repeated a column");
          expect += count;
          std::uint32_t z = run.z;
          for (std::int32_t k = 0; k < count; ++k, z += static_cast<std::uint32_t>(run.dz)) {
            if (z > depth.z_limit) fail("stepped depth beyond z_limit: it would store the clear value");
            const std::int32_t c = column + k;
            const std::uint32_t exact = sl::depth_q32(t, sl::screen_weights(t, t.edge[1].value_at(c), t.edge[2].value_at(c)));
            const std::int64_t drift = std::int64_t{z} - std::int64_t{exact > depth.z_limit ? depth.z_limit : exact};
            if (drift > depth_drift_limit(c - c0) || drift < -depth_drift_limit(c - c0)) fail("stepped depth drifted from the exact depth");
          }
        });
        if (expect != c1 + 1) fail("walk_span stopped early");
      }
      if (full_check) {
        for (std::int32_t c = c0; c <= c1; ++c) emitted[static_cast<std::size_t>(row * width + c)] = 1;
      } else {
        // Spot checks: the span's ends are covered, the pixels beside them are not.
        if (!fm::pixel_covered(tri, c0, row) || !fm::pixel_covered(tri, c1, row)) fail("span end not covered by the rule");
        if ((c0 > 0 && fm::pixel_covered(tri, c0 - 1, row)) || (c1 + 1 < width && fm::pixel_covered(tri, c1 + 1, row)))
          fail("pixel beside a span covered by the rule");
      }
    });
  }
  // The small-triangle setup, where it takes the triangle, covers the same pixels.
  sl::SmallTriangle small{};
  bool small_covers = false;
  const bool is_small = sl::setup_small(v, cull, height, small, small_covers);
  std::vector<std::uint8_t> emitted_small(emitted.size(), 0);
  if (is_small && small_covers) {
    for (std::int32_t row = small.row_begin; row < small.row_end; ++row) {
      std::int32_t lo = -small.column0, hi = width - 1 - small.column0;
      if (small.columns(lo, hi)) {
        if (row < 0 || row >= height || small.column0 + lo < 0 || small.column0 + hi >= width)
          fail("small triangle span outside the viewport");
        if (full_check)
          for (std::int32_t c = lo; c <= hi; ++c) emitted_small[static_cast<std::size_t>(row * width + small.column0 + c)] = 1;
      }
      small.next_row();
    }
  }
  if (!full_check) return;
  // The reference: float_model's rule, with float_model's `back` culling (zero area counts as culled).
  std::vector<std::uint8_t> reference(emitted.size(), 0);
  if (!(cull == sl::Cull::back && fm::is_back_facing({tri[0], tri[1], tri[2]})))
    for (const auto& [x, y] : fm::covered_pixels(tri, width, height)) reference[static_cast<std::size_t>(y * width + x)] = 1;
  if (emitted != reference) fail("covered pixels differ from float_model::covered_pixels");
  if (is_small && emitted_small != reference) fail("the small-triangle setup covers other pixels than the rule");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in{data, size};
  const std::uint64_t flags = in.next(8);
  const bool clip_mode = (flags & 1) != 0;
  const sl::Cull cull = (flags & 2) ? sl::Cull::back : sl::Cull::none;
  const bool big = (flags & 0xF0) == 0xF0;
  const int width = static_cast<int>(in.in(1, big ? 4096 : 512, 16));
  const int height = static_cast<int>(in.in(1, big ? 4096 : 512, 16));

  sl::ClipVertex<P> cv[3]{};
  for (sl::ClipVertex<P>& c : cv) {
    c.u = static_cast<std::int32_t>(in.in(-(1 << 29) + 1, (1 << 29) - 1, 32));
    c.v = static_cast<std::int32_t>(in.in(-(1 << 29) + 1, (1 << 29) - 1, 32));
    c.proj[0] = {in.in(-clip_limit, clip_limit, 64), in.in(-clip_limit, clip_limit, 64), in.in(-clip_limit, clip_limit, 64),
                 in.in(-clip_limit, clip_limit, 64)};
  }
  if (!clip_mode) {
    sl::ScreenVertex v[3]{};
    for (sl::ScreenVertex& s : v) {
      s.x = static_cast<std::int32_t>(in.in(-guard_limit, guard_limit, 24));
      s.y = static_cast<std::int32_t>(in.in(-guard_limit, guard_limit, 24));
      s.z = static_cast<std::int32_t>(in.in(0, 1 << 30, 32));
      s.inv_w_mantissa = static_cast<std::uint32_t>(in.in(std::int64_t{1} << 30, (std::int64_t{1} << 31) - 1, 32));
      s.inv_w_exponent = static_cast<int>(in.in(31, 94, 8));
    }
    const sl::ClipVertex<P>* corners[3] = {&cv[0], &cv[1], &cv[2]};
    check_triangle(v, corners, cull, width, height, in);
    return 0;
  }
  // Clip mode: positions within the transform's bound, scaled down by a shift
  // from the input so that small, ordinary values are common too.
  sl::ClipPolygon<P> poly{};
  poly.count = 3;
  for (int k = 0; k < 3; ++k) {
    poly.v[k] = cv[k];
    const int shift = static_cast<int>(in.in(0, 40, 8));
    auto component = [&] { return in.in(-clip_limit, clip_limit, 64) >> shift; };
    poly.v[k].clip = {component(), component(), component(), component()};
  }
  const std::int64_t guard = sl::guard_band(width, height);
  // SPANLIGHT_FUZZ_VERBOSE=1: print the clip-space polygon before and after clipping (to debug a crash input).
  static const bool verbose = std::getenv("SPANLIGHT_FUZZ_VERBOSE") != nullptr;
  auto print = [&](const char* what) {
    if (!verbose) return;
    std::fprintf(stderr, "%s (viewport %dx%d, guard %lld):\n", what, width, height, static_cast<long long>(guard));
    for (int k = 0; k < poly.count; ++k) {
      const sl::Vec4Wide& c = poly.v[k].clip;
      std::fprintf(stderr, "  x %lld y %lld z %lld w %lld  (x/w %g, y/w %g)\n", static_cast<long long>(c.x),
                   static_cast<long long>(c.y), static_cast<long long>(c.z), static_cast<long long>(c.w),
                   static_cast<double>(c.x) / static_cast<double>(c.w), static_cast<double>(c.y) / static_cast<double>(c.w));
    }
  };
  print("clip-space triangle");
  const bool kept = sl::clip_polygon(poly, guard, 0, 1);
  print("clipped polygon");
  if (!kept) return 0;
  // A cut point lies between the inside vertex and the plane (crossing() rounds
  // its divisor up), so it is inside every plane clipped before, up to lerp's
  // rounding: not behind the eye and within setup's guard band. w == 0 is the
  // eye itself, reached when an edge runs through it (project.hpp takes w as 1
  // raw there; seed regression_clip_through_eye).
  for (int k = 0; k < poly.count; ++k) {
    const sl::Vec4Wide& c = poly.v[k].clip;
    if (c.w < 0 || c.z + c.w < -64) fail("a clipped vertex is behind the eye or the near plane");
    const std::int64_t band = guard * (c.w >> 2) + 16;  // quarter values: no overflow
    if ((c.x >> 2) > band || -(c.x >> 2) > band || (c.y >> 2) > band || -(c.y >> 2) > band)
      fail("a clipped vertex is outside the guard band");
  }
  sl::ScreenVertex screen[sl::max_clipped_vertices];
  for (int k = 0; k < poly.count; ++k) screen[k] = sl::project(poly.v[k].clip, width, height);
  for (int k = 1; k + 1 < poly.count; ++k) {
    const sl::ScreenVertex corners[3] = {screen[0], screen[k], screen[k + 1]};
    const sl::ClipVertex<P>* clip_corners[3] = {&poly.v[0], &poly.v[k], &poly.v[k + 1]};
    check_triangle(corners, clip_corners, cull, width, height, in);
  }
  return 0;
}
