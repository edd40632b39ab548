// Issue 6, the attribute half: on seeded random triangles (random_triangle_scenes.hpp)
// the values the fixed pipeline's eye pass hands each covered pixel (depth,
// uv, each projector's s/q and t/q) stay within the error its own budget allows
// (attribute_error_budget.hpp) of the float model's perspective-correct values
// at the same pixel centre.
//
// The reference is the float model's raster (fm::rasterize_clipped) on the
// inputs the pipeline got from prepare, read back exactly, with clip x, y set
// so that it snaps to the pipeline's own subpixels: same vertices, same pixels
// (checked), so every covered pixel is compared, triangle edges included. The
// sweep's coordinate maps (host_tools/sweep) do not fit here: they let each
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
#include "random_triangle_scenes.hpp"

namespace fm = spanlight::float_model;
namespace pt = spanlight::ptest;
namespace budget = spanlight::ptest::budget;

namespace {

constexpr int P = 4;  // HostFeatures' projector count
constexpr int projectors = static_cast<int>(pt::RandomTriangles::projector_images.size());
constexpr std::uint32_t seed = 0x5eed0006;  // issue 6
constexpr double q28 = 0x1p28;

// What the eye pass hands every covered pixel, in walk order (one triangle: each pixel once).
struct PixelRecorder {
  std::vector<std::pair<std::int32_t, spanlight::PointValues<P>>>* out;
  int projector_count;
  spanlight::SpanNeeds needs() const { return {true, 0, projector_count}; }
  void object(const spanlight::ObjectData&) {}
  template <typename V>
  void pixel(std::int32_t i, const V& v) {
    out->emplace_back(i, v);
  }
};

// ---- the reference -----------------------------------------------------------------

struct ReferencePixel {
  std::int32_t index;
  double depth;     // window depth
  double lambda[3];  // screen-space barycentrics
  double divisor;   // sum lambda_i / w_i: the screen-linear divisor, up to scale
  double u, v;      // texels
  double s[projectors], t[projectors], q[projectors];  // interpolated s, t, q (not the ratios)
};

struct Reference {
  std::vector<ReferencePixel> pixels;  // row by row, left to right: the pipeline's walk order
  double w[3] = {};                    // clip w per vertex
  double u[3] = {}, v[3] = {};         // texels
  int uv_frac_bits = 0;
  double s[projectors][3] = {}, t[projectors][3] = {}, q[projectors][3] = {};
  double unit[projectors] = {};        // one unit after normalise_projector()'s shift
  double texels[projectors] = {};
};

glm::dmat4 to_dmat4(const spanlight::Mat4Block& m) {
  glm::dmat4 out(0.0);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) out[c][r] = fixedpoint::mat4_block_entry(m, c, r);
  return out;
}

Reference reference_of(const spanlight::PreparedScene& scene) {
  const spanlight::ObjectData& o = scene.objects[0];
  fm::ObjectTransform transform;
  transform.clip_from_object = to_dmat4(o.clip_from_object);
  for (int j = 0; j < scene.projector_count; ++j)
    transform.projector_from_object.push_back(to_dmat4(o.projector_from_object[j]));
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
    // normalise_projector() shifts all twelve Q31.32 values below 2^30 (one more bit for safety at
    // a power of two: the reference's raw values may differ from the pipeline's by a unit).
    double largest = 0.0;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec4& x = tri[k].projector[static_cast<std::size_t>(j)];
      ref.s[j][k] = x.x;
      ref.t[j][k] = x.y;
      ref.q[j][k] = x.w;
      for (int c = 0; c < 4; ++c) largest = std::max(largest, std::fabs(x[c]) * 0x1p32);
    }
    const int shift = std::max(0, fixedpoint::bit_length(static_cast<std::uint64_t>(largest) + 2) - 30);
    ref.unit[j] = std::ldexp(1.0, shift - 32);
    const spanlight::TextureData& image = scene.textures[scene.projectors[j].texture];
    ref.texels[j] = std::max(image.width, image.height);
  }

  // Clip x, y that the float model snaps to the pipeline's subpixels (w, z and the attributes as they are).
  for (std::uint32_t k = 0; k < 3; ++k) {
    const spanlight::ScreenVertex sv = pt::pipeline_screen_vertex(scene, o, k);
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

// One pixel's bounds at an exact point, and how far off linear_headroom()'s divisors may be
// (relative to their own value); projector < 0 where q is within its error of 0.
struct ExactBounds {
  double weights_sum_low;  // the budget's premise: far above its sum of c_i (attribute_error_budget.hpp)
  double uv, uv_rho;
  double projector[projectors], projector_rho[projectors];
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
  double weights_sum_low = INFINITY;
};

// The pipeline fills a span's inside from its two exact ends (RowInterpolation) when q > 0 at
// both and no value is clamped; then every subdivision point inside is held to
// budget::row_interpolated(), not to its own exact bound. One triangle: a row is one span, its
// first and last pixels the ends.
void bound_row_interpolation(const Reference& ref, const std::vector<std::pair<std::int32_t, spanlight::PointValues<P>>>& fixed,
                             std::vector<ExactBounds>& bounds, std::size_t begin, std::size_t end, double eps_reciprocal) {
  if (end - begin < 3) return;  // no pixel inside
  const std::size_t a = begin, b = end - 1;
  const spanlight::PointValues<P>& fa = fixed[a].second;
  const spanlight::PointValues<P>& fb = fixed[b].second;
  const ExactBounds ea = bounds[a], eb = bounds[b];
  {
    // RowInterpolation::init shifts the uv divisors (< 3 * 2^30) by one bit at most: 2 / S more.
    const double d_a = ea.uv_divisor + 2.0 / ea.weights_sum_low, d_b = eb.uv_divisor + 2.0 / eb.weights_sum_low;
    const double uv_unit = std::ldexp(1.0, -ref.uv_frac_bits);
    const double delta = std::max(std::abs(fb.u - fa.u), std::abs(fb.v - fa.v)) * uv_unit;
    const double inside = budget::row_interpolated(ea.uv, eb.uv, delta, d_a, d_b, eps_reciprocal, uv_unit);
    const double rho = std::max(ea.uv_rho, eb.uv_rho) + against_fixed(std::max(2.0 / ea.weights_sum_low, 2.0 / eb.weights_sum_low));
    for (std::size_t i = a + 1; i < b; ++i) {
      bounds[i].uv = inside;
      bounds[i].uv_rho = rho;
    }
  }
  for (int j = 0; j < projectors; ++j) {
    bool fills = fa.front[j] && fb.front[j] && ea.projector[j] >= 0.0 && eb.projector[j] >= 0.0;
    for (const spanlight::PointValues<P>* f : {&fa, &fb}) {
      for (const std::int32_t x : {f->s[j], f->t[j], f->r[j]}) fills = fills && std::abs(x) < spanlight::proj_limit;
    }
    if (!fills) continue;  // the inside is evaluated exactly, pixel by pixel: its own bounds hold
    // init brings the larger divisor into [2^30, 2^31): the smaller loses up to 2^-30 D_max / D_min,
    // D the fixed divisors (the true ones within the relative d_a, d_b).
    const double da_true = ref.pixels[a].q[j] * ref.pixels[a].divisor, db_true = ref.pixels[b].q[j] * ref.pixels[b].divisor;
    const double spread = std::max(da_true, db_true) / std::min(da_true, db_true) *
                          (1.0 + std::max(ea.projector_divisor[j], eb.projector_divisor[j])) /
                          (1.0 - std::max(ea.projector_divisor[j], eb.projector_divisor[j]));
    const double shift = 0x1p-30 * spread;
    const double d_a = ea.projector_divisor[j] + shift, d_b = eb.projector_divisor[j] + shift;
    const double delta = std::max(std::abs(fb.s[j] - fa.s[j]), std::abs(fb.t[j] - fa.t[j])) / q28 * ref.texels[j];
    const double inside = budget::row_interpolated(ea.projector[j], eb.projector[j], delta, d_a, d_b, eps_reciprocal,
                                                   ref.texels[j] / q28);
    const double rho = std::max(ea.projector_rho[j], eb.projector_rho[j]) + against_fixed(shift);
    for (std::size_t i = a + 1; i < b; ++i) {
      bounds[i].projector[j] = inside;
      bounds[i].projector_rho[j] = rho;
    }
  }
}

// The row's largest exact bound, divisor error and value range for one group (uv: -1).
struct RowGroup {
  double exact = 0.0, rho = 0.0, range = 0.0;
  bool bounded = true;
};

RowGroup row_group(const Reference& ref, const std::vector<ExactBounds>& bounds, std::size_t begin, std::size_t end,
                   int group) {
  RowGroup g;
  double d_min = INFINITY, d_max = 0.0;
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (std::size_t i = begin; i < end; ++i) {
    const ReferencePixel& p = ref.pixels[i];
    const ExactBounds& b = bounds[i];
    double e, rho, d, value[2];
    if (group < 0) {
      e = b.uv, rho = b.uv_rho, d = p.divisor, value[0] = p.u, value[1] = p.v;
    } else {
      e = b.projector[group], rho = b.projector_rho[group], d = p.q[group] * p.divisor;
      value[0] = p.s[group] / p.q[group], value[1] = p.t[group] / p.q[group];
    }
    if (e < 0.0) g.bounded = false;  // a segment may end at that pixel: nothing to start a bound from
    g.exact = std::max(g.exact, e);
    g.rho = std::max(g.rho, rho);
    d_min = std::min(d_min, d);
    d_max = std::max(d_max, d);
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], value[k]);
      hi[k] = std::max(hi[k], value[k]);
    }
  }
  g.rho += 0x1p-30 * d_max / d_min;
  if (group < 0) {
    g.range = hi[0] - lo[0] + hi[1] - lo[1];
  } else {
    // Segments without a clamped end hold true values within 4 + E of 0 (q > 0: monotonic along them).
    const double limit = 4.0 + g.exact / ref.texels[group];
    for (int k = 0; k < 2; ++k) g.range += std::clamp(hi[k], -limit, limit) - std::clamp(lo[k], -limit, limit);
    g.range *= ref.texels[group];
  }
  if (g.rho > 1.0 / 3.0) g.bounded = false;  // the stepped bound's derivation needs rho <= 1/3
  return g;
}

template <int TableBits, int NewtonSteps>
void check_triangle(const spanlight::PreparedScene& scene, const Setting& setting, Tally& tally) {
  using F = spanlight::HostFeatures<spanlight::PixelFormat::rgb888, TableBits, NewtonSteps>;
  spanlight::Precision precision{};
  precision.span_log2 = static_cast<std::uint8_t>(setting.span_log2);
  precision.span_tolerance_log2 = static_cast<std::uint8_t>(setting.tolerance_log2);
  std::vector<std::pair<std::int32_t, spanlight::PointValues<P>>> fixed;
  PixelRecorder recorder{&fixed, scene.projector_count};
  spanlight::draw_pass<F>(scene, spanlight::PassView{scene.width, scene.height, -1}, precision, recorder);

  const Reference ref = reference_of(scene);
  ++tally.triangles;
  bool same_pixels = fixed.size() == ref.pixels.size();
  for (std::size_t i = 0; same_pixels && i < fixed.size(); ++i) same_pixels = fixed[i].first == ref.pixels[i].index;
  if (!same_pixels) {
    ++tally.coverage_mismatches;
    return;
  }

  const double eps_reciprocal = budget::reciprocal_relative(TableBits, NewtonSteps);
  std::vector<ExactBounds> bounds;
  bounds.reserve(ref.pixels.size());
  for (const ReferencePixel& p : ref.pixels) {
    bounds.push_back(exact_bounds(ref, p, eps_reciprocal));
    tally.weights_sum_low = std::min(tally.weights_sum_low, bounds.back().weights_sum_low);
  }
  const double depth_bound = budget::depth_lsb(std::min({ref.w[0], ref.w[1], ref.w[2]}));
  const bool exact_everywhere = setting.span_log2 == 0;  // span 1: every pixel is an exact point
  const double uv_unit = std::ldexp(1.0, -ref.uv_frac_bits);

  for (std::size_t begin = 0; begin < ref.pixels.size();) {
    const std::int32_t row = ref.pixels[begin].index / scene.width;
    std::size_t end = begin;
    while (end < ref.pixels.size() && ref.pixels[end].index / scene.width == row) ++end;
    bound_row_interpolation(ref, fixed, bounds, begin, end, eps_reciprocal);
    RowGroup groups[1 + projectors];
    for (int g = -1; g < projectors; ++g) groups[g + 1] = row_group(ref, bounds, begin, end, g);
    for (int g = 0; g <= projectors; ++g) tally.skipped_rows += !exact_everywhere && !groups[g].bounded;

    for (std::size_t i = begin; i < end; ++i) {
      const ReferencePixel& p = ref.pixels[i];
      const spanlight::PointValues<P>& v = fixed[i].second;
      tally.depth.add(std::fabs(v.z - p.depth * 0x1p30), depth_bound);

      const double uv_error = std::max(std::fabs(v.u * uv_unit - p.u), std::fabs(v.v * uv_unit - p.v));
      const RowGroup& uv = groups[0];
      if (exact_everywhere) {
        tally.uv.add(uv_error, bounds[i].uv);
      } else if (uv.bounded) {
        tally.uv.add(uv_error,
                     budget::stepped(uv.exact, uv.rho, uv.range, setting.tolerance_log2, setting.span_log2, uv_unit));
      }

      for (int j = 0; j < projectors; ++j) {
        if (bounds[i].projector[j] < 0.0) {  // q within its own error of 0
          ++tally.behind;
          continue;
        }
        tally.wrong_side += !v.front[j];  // q~ > 0 wherever q exceeds its error
        const double err = std::max(std::fabs(v.s[j] / q28 - std::clamp(p.s[j] / p.q[j], -4.0, 4.0)),
                                    std::fabs(v.t[j] / q28 - std::clamp(p.t[j] / p.q[j], -4.0, 4.0))) * ref.texels[j];
        const RowGroup& g = groups[1 + j];
        if (exact_everywhere) {
          tally.projector.add(err, bounds[i].projector[j]);
        } else if (g.bounded) {
          tally.projector.add(err, budget::stepped(g.exact, g.rho, g.range, setting.tolerance_log2, setting.span_log2,
                                                   ref.texels[j] / q28));
        }
      }
    }
    begin = end;
  }
}

template <int TableBits, int NewtonSteps>
void check_random_triangles(const Setting& setting) {
  REQUIRE(setting.table_bits == TableBits);
  REQUIRE(setting.newton_steps == NewtonSteps);
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
    check_triangle<TableBits, NewtonSteps>(prepared->scene, setting, tally);
  }
  const std::string lines[3] = {tally.depth.describe("depth", "lsb"), tally.uv.describe("uv", "texel"),
                                tally.projector.describe("s/q,t/q", "texel")};
  std::printf("%s: %lld triangles (%lld refused by prepare), %lld projector pixels with q within its error of 0, "
              "%lld rows unbounded\n  %s\n  %s\n  %s\n",
              setting.name, tally.triangles, tally.refused, tally.behind, tally.skipped_rows, lines[0].c_str(),
              lines[1].c_str(), lines[2].c_str());
  INFO(lines[0]);
  INFO(lines[1]);
  INFO(lines[2]);
  INFO(tally.refused << " refused by prepare, " << tally.behind << " projector pixels with q within its error of 0, "
                     << tally.skipped_rows << " rows whose divisors are too uncertain for the stepped bound");
  CHECK(tally.refused <= cases / 20);
  CHECK(tally.weights_sum_low >= 0x1p13);
  CHECK(tally.coverage_mismatches == 0);
  CHECK(tally.wrong_side == 0);
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
  check_random_triangles<12, 2>({"span 1, table 12, newton 2", 0, 3, 12, 2});
}

TEST_CASE("on random triangles fixed depth, uv and projector s/q, t/q stay within their derived error of the float "
          "model at the default knobs (span 16, tolerance 2^-3, table 8, newton 1)",
          "[attributes]") {
  const spanlight::Precision defaults{};
  REQUIRE(defaults.span_log2 == 4);
  REQUIRE(defaults.span_tolerance_log2 == 3);
  check_random_triangles<8, 1>({"span 16, tolerance 3, table 8, newton 1", 4, 3, 8, 1});
}

TEST_CASE("on random triangles fixed depth, uv and projector s/q, t/q stay within their derived error of the float "
          "model at the coarsest knobs (span 64, tolerance 2^-1, table 6, no Newton step)",
          "[attributes]") {
  check_random_triangles<6, 0>({"span 64, tolerance 1, table 6, newton 0", 6, 1, 6, 0});
}
