// Span subdivision: between exact evaluations the pipeline steps uv and each
// projector's s/q, t/q linearly, and span.hpp promises to shorten a segment
// whenever linear stepping would drift more than 2^-span_tolerance_log2
// texel from the perspective-correct value. Checked pixel by pixel against
// the same walk at span 1, where every pixel is an exact evaluation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "pipeline_support.hpp"

namespace pt = spanlight::ptest;
using spanlight::PointValues;

namespace {

constexpr int P = 4;  // HostFeatures' projector count
// A 12-bit table and two Newton steps: each reciprocal is good to about
// 2^-29 relative (fixedpoint/reciprocal.hpp), so the exact evaluations the
// walk starts from are as exact as the pipeline can make them.
using F = spanlight::HostFeatures<spanlight::PixelFormat::rgb888, 12, 2>;

struct Sample {
  int object;
  PointValues<P> values;
};

// Every covered pixel of the eye pass with uv (textured objects) and all projectors.
struct ValueRecorder {
  std::vector<Sample>* out;
  const spanlight::PreparedScene* scene;
  const spanlight::ObjectData* current = nullptr;
  int object_index = -1;
  spanlight::SpanNeeds needs() const { return {current->texture >= 0, 0, scene->projector_count}; }
  void object(const spanlight::ObjectData& o) {
    current = &o;
    ++object_index;
  }
  template <typename V>
  void pixel(std::int32_t, const V& v) {
    out->push_back({object_index, v});
  }
};

std::vector<Sample> walk(const spanlight::PreparedScene& scene, int span_log2) {
  std::vector<Sample> out;
  ValueRecorder recorder{&out, &scene};
  spanlight::Precision precision{};
  precision.span_log2 = static_cast<std::uint8_t>(span_log2);
  spanlight::draw_pass<F>(scene, spanlight::PassView{scene.width, scene.height, -1}, precision, recorder);
  return out;
}

// The bound, in texels of the image the values index:
//   2^-3   what linear_headroom() allows (span_tolerance_log2 = 3); for
//          v = (a + b x) / (c + d x) the gap between the curve and its chord
//          is at most |dv| |dD| / (4 min D) exactly (D the screen-linear
//          divisor), so this is a true bound, not a first-order estimate;
//   2^-8   linear_headroom() sees the texel distance truncated to 1/256 texel;
//   2^-8   the exact evaluations at both ends and at the pixel itself, each
//          with two reciprocals good to 2^-29 relative and Q0.30 weights;
//          step_of() truncates each step by < 2^-28, 64 steps at most.
constexpr double bound_texels = 1.0 / 8.0 + 2.0 / 256.0;

struct Worst {
  double texels = 0.0;
  std::size_t at = 0;
  int checked = 0;
};

void check_stepping(const std::string& label, const spanlight::PreparedScene& scene, int span_log2) {
  const std::vector<Sample> exact = walk(scene, 0);
  const std::vector<Sample> stepped = walk(scene, span_log2);
  REQUIRE(exact.size() == stepped.size());  // the same pixels in the same order

  std::vector<Worst> worst_projector(scene.projector_count), worst_uv(scene.object_count);
  constexpr double q28 = 268435456.0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    const PointValues<P>& e = exact[i].values;
    const PointValues<P>& s = stepped[i].values;
    const auto o = static_cast<std::size_t>(exact[i].object);
    const spanlight::ObjectData& object = scene.objects[o];
    if (object.texture >= 0) {
      const double err = std::max(std::fabs(double(s.u) - e.u), std::fabs(double(s.v) - e.v)) /
                         std::ldexp(1.0, object.uv_frac_bits);
      ++worst_uv[o].checked;
      if (err > worst_uv[o].texels) worst_uv[o] = {err, i, worst_uv[o].checked};
    }
    for (int j = 0; j < scene.projector_count; ++j) {
      // Behind the projector the values are a fixed sentinel; at +-4 they are
      // clamped (not the ratio any more): neither is a value to compare with.
      if (!e.front[j] || std::abs(e.s[j]) >= spanlight::proj_limit || std::abs(e.t[j]) >= spanlight::proj_limit) continue;
      const spanlight::TextureData& image = scene.textures[scene.projectors[j].texture];
      const double texels = std::max(image.width, image.height);
      const double err = std::max(std::fabs(double(s.s[j]) - e.s[j]), std::fabs(double(s.t[j]) - e.t[j])) / q28 * texels;
      Worst& w = worst_projector[static_cast<std::size_t>(j)];
      ++w.checked;
      if (err > w.texels) w = {err, i, w.checked};
    }
  }
  for (std::size_t o = 0; o < worst_uv.size(); ++o) {
    if (worst_uv[o].checked == 0) continue;
    INFO(label << " object " << o << ": worst uv drift " << worst_uv[o].texels << " texel over " << worst_uv[o].checked
               << " pixels (bound " << bound_texels << ")");
    CHECK(worst_uv[o].texels <= bound_texels);
  }
  for (std::size_t j = 0; j < worst_projector.size(); ++j) {
    const Worst& w = worst_projector[j];
    const PointValues<P>& e = exact[w.at].values;
    const PointValues<P>& s = stepped[w.at].values;
    INFO(label << " projector " << j << ": worst s/q, t/q drift " << w.texels << " texel over " << w.checked
               << " pixels (bound " << bound_texels << "); there exact s/q " << e.s[j] / q28 << " t/q " << e.t[j] / q28
               << ", stepped " << s.s[j] / q28 << ", " << s.t[j] / q28);
    CHECK(w.checked > 0);
    CHECK(w.texels <= bound_texels);
  }
}

}  // namespace

TEST_CASE("span stepping stays within the span tolerance of the exact values on every shared scene", "[span]") {
  for (const char* name : pt::shared_scene_names()) {
    const auto prepared = spanlight::prepare::prepare_scene(spanlight::scene::load_scene(pt::scene_file(name)));
    check_stepping(name, prepared->scene, 4);
  }
}

TEST_CASE("span stepping stays within the span tolerance where s/q leaves [-4, 4] inside a segment", "[span]") {
  // Near the apex of pt::apex_floor_scene()'s lit wedge s/q changes by about
  // one frustum width per pixel, so 16-pixel segments begin or end where s/q
  // is clamped to +-4 while the frustum's side lies between them.
  const auto prepared = spanlight::prepare::prepare_scene(pt::apex_floor_scene());
  for (const int span_log2 : {2, 4, 6}) check_stepping("apex floor, span 2^" + std::to_string(span_log2), prepared->scene, span_log2);
}

TEST_CASE("a one-pixel span walks without planning a zero-length segment and gives the exact values there", "[span]") {
  // Spans of one pixel (c0 == c1) happen at every triangle's tips. The walk
  // must show the exact evaluation at that pixel; the sanitizer twin also
  // checks the walk does nothing undefined on the way (no segment of length
  // 0: step_of() would take clz(0)).
  using R = F::reciprocal;
  auto vertex = [](std::int32_t x, std::int32_t y, std::int32_t z, std::uint32_t mantissa, int exponent) {
    spanlight::ScreenVertex v{};
    v.x = x;
    v.y = y;
    v.z = z;
    v.inv_w_mantissa = mantissa;
    v.inv_w_exponent = exponent;
    return v;
  };
  const spanlight::ScreenVertex v[3] = {vertex(10 * 256 + 17, 10 * 256 + 3, 1 << 28, 1u << 30, 33),
                                        vertex(12 * 256 + 90, 40 * 256 + 41, 1 << 29, 3u << 29, 34),
                                        vertex(30 * 256 + 5, 12 * 256 + 200, 3 << 28, 1u << 30, 32)};
  spanlight::TriangleSetup setup{};
  REQUIRE(spanlight::setup_triangle(v, spanlight::Cull::none, 64, 64, setup));
  spanlight::TriangleAttributes<P> attrs{};
  attrs.u0 = 3 << 16;
  attrs.du1 = 40 << 16;
  attrs.du2 = -(7 << 16);
  attrs.v0 = 1 << 16;
  attrs.dv1 = 5 << 16;
  attrs.dv2 = 60 << 16;
  const std::int32_t strq0[4] = {1 << 26, 1 << 26, 1 << 27, 1 << 28};
  const std::int32_t strq1[4] = {3 << 26, -(1 << 25), 1 << 26, 1 << 27};
  const std::int32_t strq2[4] = {-(1 << 26), 5 << 25, 1 << 25, 1 << 26};
  for (int k = 0; k < 4; ++k) {
    attrs.proj0[0][k] = strq0[k];
    attrs.proj_d1[0][k] = strq1[k];
    attrs.proj_d2[0][k] = strq2[k];
  }
  const std::uint16_t texels[P] = {256, 0, 0, 0};
  const spanlight::SpanControl control{4, 3, 16, texels};
  const spanlight::SpanNeeds needs{true, 0, 1};
  int pixels = 0;
  spanlight::rasterize_rows(setup, 64, [&](std::int32_t, std::int32_t c0, std::int32_t c1) {
    for (std::int32_t column = c0; column <= c1; ++column) {  // each pixel as a span of its own
      const std::int64_t e1 = setup.edge[1].value_at(column), e2 = setup.edge[2].value_at(column);
      const spanlight::GroupPoint uv = spanlight::evaluate_group<P, R>(setup, attrs, spanlight::uv_group, e1, e2);
      const spanlight::GroupPoint st = spanlight::evaluate_group<P, R>(setup, attrs, 0, e1, e2);
      int calls = 0;
      spanlight::walk_span<P, R>(setup, attrs, needs, control, column, column,
                                 [&](std::int32_t at, const PointValues<P>& values) {
                                   ++calls;
                                   CHECK(at == column);
                                   CHECK(values.u == uv.value[0]);
                                   CHECK(values.v == uv.value[1]);
                                   CHECK(values.s[0] == st.value[0]);
                                   CHECK(values.t[0] == st.value[1]);
                                   CHECK(values.r[0] == st.value[2]);
                                 });
      CHECK(calls == 1);
      ++pixels;
    }
  });
  CHECK(pixels > 100);
}
