// Issue 6, the attribute half: on seeded random triangles (random_triangle_scenes.hpp)
// the values the fixed pipeline's eye pass hands each covered pixel (depth,
// uv, each projector's s/q and t/q) stay within the error its own budget allows
// (attribute_error_budget.hpp) of the float model's perspective-correct values
// at the same pixel centre.
//
// What the walk hands a pixel (3_span/walk.hpp): each span's two ends are exact
// points (3_span/exact.hpp); inside, segment ends and middles come from the 1-D
// perspective interpolation of the ends (RowInterpolation) and the pixels
// between step as the quadratic through them, each segment as long as
// SegmentPlanner's closed-form bound allows (3_span/segments.hpp). A
// projector behind or outside its frustum along a whole span is held constant
// there; one whose q changes sign is evaluated exactly at every pixel.
//
// The reference is the float model's raster (fm::rasterize_clipped) on the
// inputs the pipeline got from prepare, read back exactly, with clip x, y set
// so that it snaps to the pipeline's own subpixels: same vertices, same pixels
// (checked), so every covered pixel is compared, triangle edges included. The
// sweep's coordinate maps (host_tools/measure/sweep) do not fit here: they let each
// renderer snap on its own and skip pixels near triangle edges for that reason.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ios>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "attribute_error_budget.hpp"
#include "float_model/float_model.hpp"
#include "float_model/transform.hpp"
#include "pipeline_support.hpp"
#include "spanlight/4_pixel/surface.hpp"
#include "random_triangle_scenes.hpp"

namespace fm = spanlight::float_model;
namespace pt = spanlight::ptest;
namespace budget = spanlight::ptest::budget;

namespace {

constexpr int P = pt::eye_projectors;
constexpr int projectors = static_cast<int>(pt::RandomTriangles::projector_images.size());
constexpr std::uint32_t seed = 0x5eed0006;  // issue 6
constexpr double q28 = 0x1p28;

// One pixel's values as the walk hands them (PixelRun stepped to the pixel), in the group's step scale.
struct PixelValues {
  std::uint32_t z;  // Q0.32
  std::uint32_t u, v;
  std::int32_t s[P], t[P], r[P];  // Q3.28
  bool front[P];
};

// What the eye pass hands every covered pixel, in walk order (one triangle: each pixel once).
// uv steps in the scale the object's surface sampler uses (4_pixel/surface.hpp).
struct PixelRecorder {
  static constexpr bool may_need_uv = true;
  static constexpr bool may_need_projectors = true;
  std::vector<std::pair<std::uint32_t, PixelValues>>* out;
  const spanlight::TextureData* textures;
  int projector_count;
  spanlight::StepScale scale{};
  spanlight::SpanNeeds object(const spanlight::ObjectData& o) {
    scale = spanlight::surface_of(o, textures).scale;
    return {true, scale, 0, projector_count};
  }
  spanlight::PixelRange passing(std::uint32_t, std::int32_t count, std::uint32_t, std::int32_t) const { return {0, count}; }
  void run(std::uint32_t first, std::int32_t count, const spanlight::PixelRun<P>& run) {
    spanlight::PixelRun<P> r = run;
    for (std::int32_t k = 0; k < count; ++k) {
      PixelValues v{};
      v.z = r.z;
      v.u = r.u.value;
      v.v = r.v.value;
      for (int j = 0; j < P; ++j) {
        v.s[j] = static_cast<std::int32_t>(r.s[j].value);
        v.t[j] = static_cast<std::int32_t>(r.t[j].value);
        v.r[j] = static_cast<std::int32_t>(r.r[j].value);
        v.front[j] = r.front[j];
        spanlight::step(r.s[j]);
        spanlight::step(r.t[j]);
        spanlight::step(r.r[j]);
      }
      out->emplace_back(first + static_cast<std::uint32_t>(k), v);
      r.z += static_cast<std::uint32_t>(r.dz);
      spanlight::step(r.u);
      spanlight::step(r.v);
    }
  }
};

// ---- the reference -----------------------------------------------------------------

struct ReferencePixel {
  std::int32_t index;
  double depth;     // window depth
  double lambda[3];  // screen-space barycentrics
  double divisor;   // sum lambda_i / w_i: the screen-linear divisor, up to scale
  double u, v;      // texels
  double s[projectors], t[projectors], r[projectors], q[projectors];  // interpolated s, t, r, q (not the ratios)
};

struct Reference {
  std::vector<ReferencePixel> pixels;  // row by row, left to right: the pipeline's walk order
  double w[3] = {};                    // clip w per vertex
  double u[3] = {}, v[3] = {};         // texels
  int uv_frac_bits = 0;
  double s[projectors][3] = {}, t[projectors][3] = {}, r[projectors][3] = {}, q[projectors][3] = {};
  double unit[projectors] = {};        // one unit after set_projector() (2_triangle/attributes.hpp)'s shift
  double texels[projectors] = {};
};

glm::dmat4 to_dmat4(const spanlight::Mat4Block& m) {
  glm::dmat4 out(0.0);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out[c][r] = fixedpoint::mat4_block_entry(m, c, r);
  return out;
}

Reference reference_of(const spanlight::prepare::PreparedStorage& prepared) {
  const spanlight::PreparedScene& scene = prepared.scene;
  const spanlight::ObjectData& o = scene.objects[0];
  fm::ObjectTransform transform;
  transform.clip_from_object = to_dmat4(prepared.matrices.clip_from_object[0]);
  for (int j = 0; j < scene.projector_count; ++j)
    transform.projector_from_object.push_back(to_dmat4(prepared.matrices.projector_from_object[j]));
  spanlight::scene::Mesh mesh;
  const double uv_unit = std::ldexp(1.0, -o.uv_frac_bits);
  for (int k = 0; k < 3; ++k) {
    const std::int32_t* q16 = o.positions + 3 * k;
    mesh.positions.emplace_back(q16[0] / 65536.0, q16[1] / 65536.0, q16[2] / 65536.0);
    mesh.uvs.emplace_back(o.uvs[2 * k] * uv_unit, o.uvs[2 * k + 1] * uv_unit);  // texels
  }
  mesh.triangles = {{0, 1, 2}};
  transform.uvs = mesh.uvs;
  fm::ClipTriangle tri = fm::transform_triangle(transform, mesh, 0);

  Reference ref;
  ref.uv_frac_bits = o.uv_frac_bits;
  for (int k = 0; k < 3; ++k) {
    ref.w[k] = tri[k].position.w;
    ref.u[k] = tri[k].uv.x;
    ref.v[k] = tri[k].uv.y;
  }
  for (int j = 0; j < projectors; ++j) {
    // set_projector() (2_triangle/attributes.hpp) shifts all twelve Q31.32 values below 2^30 (one more bit for safety at
    // a power of two: the reference's raw values may differ from the pipeline's by a unit).
    double largest = 0.0;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec4& x = tri[k].projector[static_cast<std::size_t>(j)];
      ref.s[j][k] = x.x;
      ref.t[j][k] = x.y;
      ref.r[j][k] = x.z;
      ref.q[j][k] = x.w;
      for (int c = 0; c < 4; ++c) largest = std::max(largest, std::fabs(x[c]) * 0x1p32);
    }
    const int shift = std::max(0, fixedpoint::bit_length(static_cast<std::uint64_t>(largest) + 2) - 30);
    ref.unit[j] = std::ldexp(1.0, shift - 32);
    const spanlight::TextureLevel& image = scene.textures[scene.projectors[j].texture].levels[0];
    ref.texels[j] = std::max(image.width, image.height);
  }

  // Clip x, y that the float model snaps to the pipeline's subpixels (w, z and the attributes as they are).
  for (std::uint32_t k = 0; k < 3; ++k) {
    const spanlight::ScreenVertex sv = pt::eye_screen_vertex(scene, prepared.matrices, 0, k);
    glm::dvec4& c = tri[k].position;
    c.x = (sv.x / 256.0 / scene.width * 2.0 - 1.0) * c.w;
    c.y = (1.0 - sv.y / 256.0 / scene.height * 2.0) * c.w;
    const fm::SnappedVertex back = fm::snap(fm::to_window(c, scene.width, scene.height));
    REQUIRE(back.x == sv.x);
    REQUIRE(back.y == sv.y);
  }
  fm::rasterize_clipped(tri, {scene.width, scene.height}, spanlight::scene::Cull::none,
                        [&](const fm::ClipTriangle& t, const fm::Fragment& f) {
    ReferencePixel p{};
    p.index = f.y * scene.width + f.x;
    p.depth = f.depth;
    for (int i = 0; i < 3; ++i) {
      p.lambda[i] = f.lambda[i];
      p.divisor += f.lambda[i] / t[i].position.w;
    }
    const glm::dvec2 uv = fm::interpolate_uv(t, f);
    p.u = uv.x;
    p.v = uv.y;
    for (int j = 0; j < projectors; ++j) {
      const glm::dvec4 strq = fm::interpolate_projector(t, f, static_cast<std::size_t>(j));
      p.s[j] = strq.x;
      p.t[j] = strq.y;
      p.r[j] = strq.z;
      p.q[j] = strq.w;
    }
    ref.pixels.push_back(p);
  });
  return ref;
}

// ---- the bounds, per pixel and per row ------------------------------------------------

struct Setting {
  const char* name;
  int span_log2, tolerance_log2, table_bits, newton_steps;
};

// One pixel's bounds at an exact point, and how far off RowInterpolation's divisors may be
// (relative to their own value); projector < 0 where q is within its error of 0.
struct ExactBounds {
  double weights_sum_low;  // the budget's premise: far above its sum of c_i (attribute_error_budget.hpp)
  double uv, uv_rho;
  double projector[projectors], projector_rho[projectors];
  double projector_r[projectors];  // r/q's bound (the same divide as s/q's), in r/q; < 0 as projector
  double uv_divisor, projector_divisor[projectors];  // the divisors' relative error against the truth
};

// A relative error c against the truth, as one against the fixed value: c / (1 - c).
double against_fixed(double c) { return c / (1.0 - c); }

ExactBounds exact_bounds(const Reference& ref, const ReferencePixel& p, double eps_reciprocal) {
  const double eps_omega = budget::omega_relative(std::min({ref.w[0], ref.w[1], ref.w[2]}));
  const budget::Weights w = budget::weights(p.lambda, ref.w, eps_omega, eps_reciprocal);
  ExactBounds b{};
  b.weights_sum_low = w.sum_low;
  b.uv = std::max(budget::uv_exact(ref.u, p.u, w, ref.uv_frac_bits), budget::uv_exact(ref.v, p.v, w, ref.uv_frac_bits));
  b.uv_rho = against_fixed(w.divisor_relative);
  b.uv_divisor = w.divisor_relative;
  for (int j = 0; j < projectors; ++j) {
    budget::ProjectorPoint point{};
    for (int k = 0; k < 3; ++k) {
      point.s[k] = ref.s[j][k];
      point.t[k] = ref.t[j][k];
      point.q[k] = ref.q[j][k];
    }
    point.unit = ref.unit[j];
    point.s_value = p.s[j];
    point.t_value = p.t[j];
    point.q_value = p.q[j];
    const double e = budget::projector_exact(point, w);
    b.projector[j] = e < 0.0 ? -1.0 : e * ref.texels[j];
    budget::ProjectorPoint r_point = point;  // r in place of s and t: the bound of r/q alone
    for (int k = 0; k < 3; ++k) r_point.s[k] = r_point.t[k] = ref.r[j][k];
    r_point.s_value = r_point.t_value = p.r[j];
    b.projector_r[j] = budget::projector_exact(r_point, w);
    // The projector's divisor is q~ times the weights' sum: the relative errors compound.
    const double c = (1.0 + budget::q_error(point, w) / p.q[j]) * (1.0 + w.divisor_relative) - 1.0;
    b.projector_rho[j] = against_fixed(c);
    b.projector_divisor[j] = c;
  }
  return b;
}

struct Worst {
  double error = 0.0, bound = 0.0;  // the largest error seen, and the bound where it was
  double ratio = 0.0;               // the largest error / bound
  long long pixels = 0, over = 0;
  void add(double err, double bound_here) {
    ++pixels;
    if (err > bound_here) ++over;
    if (err > error) {
      error = err;
      bound = bound_here;
    }
    if (bound_here > 0.0 && err / bound_here > ratio) ratio = err / bound_here;
  }
  std::string describe(const char* what, const char* unit) const {
    char line[200];
    std::snprintf(line, sizeof line, "%-8s worst %.3g %s (bound there %.3g), worst error/bound %.3f, %lld pixels, %lld over",
                  what, error, unit, bound, ratio, pixels, over);
    return line;
  }
};

struct Tally {
  Worst depth, uv, projector;
  long long triangles = 0, refused = 0, coverage_mismatches = 0, behind = 0, wrong_side = 0, skipped_rows = 0;
  long long interpolated_rows = 0, outside_rows = 0, outside_wrong = 0;
  double weights_sum_low = INFINITY;
};

// The fixed uv of a repeating texture in texels, and its distance to the truth modulo the size
// (the step scale wraps as the texture repeats: 4_pixel/surface.hpp).
double uv_error(std::uint32_t fixed, double truth, int x_shift) {
  const double size = std::ldexp(1.0, 32 - x_shift);
  return std::fabs(std::remainder(std::ldexp(static_cast<double>(fixed), -x_shift) - truth, size));
}

// How the walk treats one group along a span (walk.hpp, GroupSpan::start), read from what it
// handed the span's pixels: the ends are exact points, except where the group is held
// constant, where every pixel shows the first one's values.
enum class Mode { interpolated, constant_behind, constant_outside, per_pixel };

Mode projector_mode(const std::vector<std::pair<std::uint32_t, PixelValues>>& fixed, std::size_t a, std::size_t b, int j) {
  const PixelValues& first = fixed[a].second;
  const PixelValues& last = fixed[b].second;
  if (!first.front[j] && !last.front[j]) return Mode::constant_behind;
  if (first.front[j] != last.front[j]) return Mode::per_pixel;
  // Held outside the frustum: one of s/q, t/q, r/q outside [0, 1] at the first pixel, and every pixel the same.
  constexpr std::int32_t one = std::int32_t{1} << spanlight::proj_frac_bits;
  bool outside = false;
  for (const std::int32_t x : {first.s[j], first.t[j], first.r[j]}) outside = outside || x < 0 || x > one;
  bool held = outside;
  for (std::size_t i = a + 1; held && i <= b; ++i) {
    const PixelValues& v = fixed[i].second;
    held = v.s[j] == first.s[j] && v.t[j] == first.t[j] && v.r[j] == first.r[j];
  }
  if (held) return Mode::constant_outside;
  bool clamped = false;
  for (const std::int32_t x : {first.s[j], first.t[j], first.r[j], last.s[j], last.t[j], last.r[j]})
    clamped = clamped || x <= -spanlight::proj_limit || x >= spanlight::proj_limit;
  return clamped ? Mode::per_pixel : Mode::interpolated;
}

// A pixel inside an interpolated span (budget::interpolated_span): its bound from the ends'
// exact bounds, the divisors' errors and the value's change along the span. Returns < 0 where
// an end's bound is not known (q within its error of 0).
double inside_bound(double end_a, double end_b, double divisor_a, double divisor_b, double delta, double eps_reciprocal,
                    double unit, const Setting& setting) {
  if (end_a < 0.0 || end_b < 0.0) return -1.0;
  return budget::interpolated_span(end_a, end_b, delta, divisor_a, divisor_b, eps_reciprocal, unit,
                                   setting.span_log2 > 0, setting.tolerance_log2);
}

void check_triangle(const spanlight::prepare::PreparedStorage& prepared, const Setting& setting, Tally& tally) {
  const spanlight::PreparedScene& scene = prepared.scene;
  spanlight::Knobs knobs;
  knobs.span_log2 = static_cast<std::uint8_t>(setting.span_log2);
  knobs.tolerance_log2 = static_cast<std::uint8_t>(setting.tolerance_log2);
  knobs.table_bits = static_cast<std::uint8_t>(setting.table_bits);
  knobs.newton = static_cast<std::uint8_t>(setting.newton_steps);
  REQUIRE(spanlight::knobs_valid(knobs));
  std::vector<std::pair<std::uint32_t, PixelValues>> fixed;
  PixelRecorder recorder{&fixed, scene.textures, scene.projector_count};
  pt::draw_eye_pass(scene, prepared.matrices, recorder, knobs);
  REQUIRE(scene.textures[scene.objects[0].texture].wrap == spanlight::Wrap::repeat);
  const int x_shift = recorder.scale.shift[0] + scene.objects[0].uv_frac_bits;  // uv steps as a fraction of the size
  REQUIRE(recorder.scale.shift[1] == recorder.scale.shift[0]);  // a square texture

  const Reference ref = reference_of(prepared);
  ++tally.triangles;
  bool same_pixels = fixed.size() == ref.pixels.size();
  for (std::size_t i = 0; same_pixels && i < fixed.size(); ++i)
    same_pixels = static_cast<std::int32_t>(fixed[i].first) == ref.pixels[i].index;
  if (!same_pixels) {
    ++tally.coverage_mismatches;
    return;
  }

  const double eps_reciprocal = budget::reciprocal_relative(setting.table_bits, setting.newton_steps);
  std::vector<ExactBounds> bounds;
  bounds.reserve(ref.pixels.size());
  for (const ReferencePixel& p : ref.pixels) {
    bounds.push_back(exact_bounds(ref, p, eps_reciprocal));
    tally.weights_sum_low = std::min(tally.weights_sum_low, bounds.back().weights_sum_low);
  }
  const double w_min = std::min({ref.w[0], ref.w[1], ref.w[2]});
  const double uv_unit = std::ldexp(1.0, -ref.uv_frac_bits);

  for (std::size_t begin = 0; begin < ref.pixels.size();) {
    const std::int32_t row = ref.pixels[begin].index / scene.width;
    std::size_t end = begin;
    while (end < ref.pixels.size() && ref.pixels[end].index / scene.width == row) ++end;
    const std::size_t a = begin, b = end - 1;  // one triangle: the row is one span, a and b its exact ends
    const double depth_bound = budget::depth_units(w_min, static_cast<int>(b - a));
    const ExactBounds& ea = bounds[a];
    const ExactBounds& eb = bounds[b];

    // uv: interpolated between the ends unless the span is one pixel.
    double uv_inside = -1.0;
    if (b > a) {
      // RowInterpolation::init shifts the uv divisors (< 3 * 2^30) by one bit at most: 2 / S more.
      const double d_a = ea.uv_divisor + 2.0 / ea.weights_sum_low, d_b = eb.uv_divisor + 2.0 / eb.weights_sum_low;
      const double delta = std::max(std::fabs(ref.pixels[b].u - ref.pixels[a].u), std::fabs(ref.pixels[b].v - ref.pixels[a].v)) +
                           ea.uv + eb.uv;  // the fixed ends' difference, at most
      uv_inside = inside_bound(ea.uv, eb.uv, d_a, d_b, delta, eps_reciprocal, uv_unit, setting);
      ++tally.interpolated_rows;
    }
    // Each projector: its mode, and the bound inside an interpolated span.
    Mode mode[projectors];
    double projector_inside[projectors];
    for (int j = 0; j < projectors; ++j) {
      mode[j] = b > a ? projector_mode(fixed, a, b, j) : Mode::per_pixel;
      projector_inside[j] = -1.0;
      if (mode[j] != Mode::interpolated) continue;
      // init brings the larger divisor into [2^30, 2^31): the smaller loses up to 2^-30 D_max / D_min,
      // D the fixed divisors (the true ones within the relative d_a, d_b).
      const double da_true = ref.pixels[a].q[j] * ref.pixels[a].divisor, db_true = ref.pixels[b].q[j] * ref.pixels[b].divisor;
      const double worst = std::max(ea.projector_divisor[j], eb.projector_divisor[j]);
      const double spread = std::max(da_true, db_true) / std::min(da_true, db_true) * (1.0 + worst) / (1.0 - worst);
      const double shift = 0x1p-30 * spread;
      auto ratio = [&](std::size_t i, const double* x) { return std::clamp(x[j] / ref.pixels[i].q[j], -4.0, 4.0); };
      const double delta = std::max(std::fabs(ratio(b, ref.pixels[b].s) - ratio(a, ref.pixels[a].s)),
                                    std::fabs(ratio(b, ref.pixels[b].t) - ratio(a, ref.pixels[a].t))) * ref.texels[j] +
                           std::max(ea.projector[j], 0.0) + std::max(eb.projector[j], 0.0);
      projector_inside[j] = inside_bound(ea.projector[j], eb.projector[j], ea.projector_divisor[j] + shift,
                                         eb.projector_divisor[j] + shift, delta, eps_reciprocal, ref.texels[j] / q28, setting);
      tally.skipped_rows += projector_inside[j] < 0.0;
    }
    for (int j = 0; j < projectors; ++j) tally.outside_rows += mode[j] == Mode::constant_outside;

    for (std::size_t i = begin; i < end; ++i) {
      const ReferencePixel& p = ref.pixels[i];
      const PixelValues& v = fixed[i].second;
      const bool at_end = i == a || i == b;
      tally.depth.add(std::fabs(static_cast<double>(v.z) - p.depth * 0x1p32), depth_bound);

      const double e_uv = std::max(uv_error(v.u, p.u, x_shift), uv_error(v.v, p.v, x_shift));
      tally.uv.add(e_uv, at_end ? bounds[i].uv : uv_inside);

      for (int j = 0; j < projectors; ++j) {
        if (bounds[i].projector[j] < 0.0) {  // q within its own error of 0
          ++tally.behind;
          continue;
        }
        tally.wrong_side += !v.front[j];  // q~ > 0 wherever q exceeds its error
        const double truth_s = std::clamp(p.s[j] / p.q[j], -4.0, 4.0), truth_t = std::clamp(p.t[j] / p.q[j], -4.0, 4.0);
        if (mode[j] == Mode::constant_outside) {
          // Held at the first pixel's values: the light is off all along, so the truth must lie outside
          // [0, 1] on the side the held value does in one of s/q, t/q, r/q. The walk holds a span whose
          // exact ends lie outside one side: with q > 0 all along each ratio is monotonic along the row,
          // so the truth at every pixel lies between the truths at the ends, and it is outside up to the
          // larger of the ends' errors (or its own, for a span held for values beyond the limit).
          if (bounds[a].projector[j] < 0.0 || bounds[b].projector[j] < 0.0) {  // an end's q within its error of 0
            ++tally.behind;
            continue;
          }
          auto widest = [&](double (ExactBounds::*member)[projectors]) {
            return std::max({(bounds[i].*member)[j], (bounds[a].*member)[j], (bounds[b].*member)[j]});
          };
          const double e_st = widest(&ExactBounds::projector) / ref.texels[j], e_r = widest(&ExactBounds::projector_r);
          const PixelValues& first = fixed[a].second;
          const std::int32_t held[3] = {first.s[j], first.t[j], first.r[j]};
          const double truth[3] = {truth_s, truth_t, p.r[j] / p.q[j]};
          bool outside = false;
          for (int k = 0; k < 3; ++k) {
            const double e = k < 2 ? e_st : e_r;
            outside = outside || (held[k] < 0 && truth[k] <= e) || (held[k] > (1 << 28) && truth[k] >= 1.0 - e);
          }
          tally.outside_wrong += !outside;
          continue;
        }
        const double err = std::max(std::fabs(v.s[j] / q28 - truth_s), std::fabs(v.t[j] / q28 - truth_t)) * ref.texels[j];
        if (at_end || mode[j] == Mode::per_pixel) {
          tally.projector.add(err, bounds[i].projector[j]);
        } else if (projector_inside[j] >= 0.0) {
          tally.projector.add(err, projector_inside[j]);
        }
      }
    }
    begin = end;
  }
}

void check_random_triangles(const Setting& setting) {
  const int cases = pt::sanitized ? 300 : 3000;
  INFO("seed 0x" << std::hex << seed << std::dec << ", " << cases << " triangles, " << setting.name);
  pt::RandomTriangles random(seed);
  Tally tally;
  for (int n = 0; n < cases; ++n) {
    const spanlight::scene::Scene s = random.next();
    std::unique_ptr<spanlight::prepare::PreparedStorage> prepared;
    try {
      prepared = spanlight::prepare::prepare_scene(s);
    } catch (const spanlight::prepare::PrepareError&) {  // a matrix entry beyond 2^13 (docs/limits.md)
      ++tally.refused;
      continue;
    }
    check_triangle(*prepared, setting, tally);
  }
  const std::string lines[3] = {tally.depth.describe("depth", "2^-32"), tally.uv.describe("uv", "texel"),
                                tally.projector.describe("s/q,t/q", "texel")};
  std::printf("%s: %lld triangles (%lld refused by prepare), %lld projector pixels with q within its error of 0, "
              "%lld projector spans unbounded, %lld held outside\n  %s\n  %s\n  %s\n",
              setting.name, tally.triangles, tally.refused, tally.behind, tally.skipped_rows, tally.outside_rows,
              lines[0].c_str(), lines[1].c_str(), lines[2].c_str());
  INFO(lines[0]);
  INFO(lines[1]);
  INFO(lines[2]);
  INFO(tally.refused << " refused by prepare, " << tally.behind << " projector pixels with q within its error of 0, "
                     << tally.skipped_rows << " projector spans whose ends are too uncertain for a bound, "
                     << tally.outside_rows << " held constant outside the frustum");
  CHECK(tally.refused <= cases / 20);
  CHECK(tally.weights_sum_low >= 0x1p13);
  CHECK(tally.coverage_mismatches == 0);
  CHECK(tally.wrong_side == 0);
  CHECK(tally.outside_wrong == 0);
  CHECK(tally.uv.pixels > 100000 / (pt::sanitized ? 10 : 1));  // not vacuous
  CHECK(tally.projector.pixels > 100000 / (pt::sanitized ? 10 : 1));
  CHECK(tally.depth.over == 0);
  CHECK(tally.uv.over == 0);
  CHECK(tally.projector.over == 0);
}

}  // namespace

TEST_CASE("on random triangles fixed depth, uv and projector s/q, t/q stay within their derived error of the float "
          "model at span 1 with a 12-bit table and two Newton steps",
          "[attributes]") {
  check_random_triangles({"span 1, table 12, newton 2", 0, 3, 12, 2});
}

TEST_CASE("on random triangles fixed depth, uv and projector s/q, t/q stay within their derived error of the float "
          "model at the default knobs (span 64, tolerance 2^-5, table 8, newton 1)",
          "[attributes]") {
  const spanlight::Knobs defaults{};
  REQUIRE(defaults.span_log2 == 6);
  REQUIRE(defaults.tolerance_log2 == 5);
  REQUIRE(defaults.table_bits == 8);
  REQUIRE(defaults.newton == 1);
  check_random_triangles({"span 64, tolerance 5, table 8, newton 1", 6, 5, 8, 1});
}

TEST_CASE("on random triangles fixed depth, uv and projector s/q, t/q stay within their derived error of the float "
          "model at the coarsest knobs (span 64, tolerance 2^-1, table 6, no Newton step)",
          "[attributes]") {
  check_random_triangles({"span 64, tolerance 1, table 6, newton 0", 6, 1, 6, 0});
}
