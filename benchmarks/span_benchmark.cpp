// The span walk (3_span/walk.hpp): one triangle's rows, per span length, for a
// pass that interpolates depth only, depth + uv, or depth + uv + one projector.
// The kernel steps each run's values to every pixel as a pass does. Reported
// per covered pixel.
#include <benchmark/benchmark.h>

#include <vector>

#include "benchmark_triangle.hpp"
#include "spanlight/3_span/divide.hpp"
#include "spanlight/3_span/walk.hpp"
#include "spanlight/4_pixel/depth.hpp"

namespace {

constexpr spanlight::FixedDivide<8, 1> divide{};

template <bool UV, bool Projectors>
std::int64_t walk_triangle(const spanlight::TriangleSetup& setup, const spanlight::TriangleAttributes<1>& attributes,
                           const spanlight::SpanNeeds& needs, const spanlight::SpanControl& control,
                           std::vector<std::uint32_t>& sink) {
  std::int64_t pixels = 0;
  spanlight::TriangleSetup t = setup;  // rasterize_rows steps the edges
  spanlight::PixelRun<1> pixel_run{};  // zeroed once a triangle, as draw.hpp does
  spanlight::rasterize_rows(t, benchmarks::width, [&](std::int32_t row, std::int32_t c0, std::int32_t c1) {
    spanlight::walk_span<1, UV, Projectors>(t, attributes, needs, control, divide, c0, c1, pixel_run,
                                            [&](std::int32_t column, std::int32_t count, const spanlight::PixelRun<1>& run) {
      std::uint32_t z = run.z;
      spanlight::Stepped u = run.u, s = run.s[0];
      std::uint32_t* out = sink.data() + row * benchmarks::width + column;
      for (std::int32_t k = 0; k < count; ++k) {
        out[k] = z + u.value + s.value;
        z += static_cast<std::uint32_t>(run.dz);
        u.value += u.step;  // two adds a pixel, as the passes step (5_frame/passes.hpp)
        u.step += u.curve;
        s.value += s.step;
        s.step += s.curve;
      }
      pixels += count;
    });
  });
  return pixels;
}

void span_walk(benchmark::State& state) {
  const int span_log2 = static_cast<int>(state.range(0));
  const int groups = static_cast<int>(state.range(1));  // 0 depth, 1 + uv, 2 + uv + projector
  const spanlight::TriangleSetup setup = benchmarks::floor_setup();
  const spanlight::TriangleAttributes<1> attributes = benchmarks::floor_attributes(setup);
  const spanlight::StepScale uv_scale{{0, 0, 0}, {0, 0, 0}, 16};  // a clamped texture, 16 sub-texel bits
  const spanlight::SpanNeeds needs{groups >= 1, uv_scale, 0, groups >= 2 ? 1 : 0};
  const std::uint16_t projector_texels[1] = {256};
  const std::uint8_t projector_texel_bits[1] = {spanlight::proj_frac_bits - 8};
  const spanlight::SpanControl control{span_log2, spanlight::Knobs{}.tolerance_log2, &uv_scale, 16, projector_texels,
                                       projector_texel_bits, spanlight::DepthFormat<>(24).z_limit};
  std::vector<std::uint32_t> sink(benchmarks::width * benchmarks::height);
  std::int64_t pixels = 0;
  for (auto _ : state) {
    if (groups == 0) pixels += walk_triangle<false, false>(setup, attributes, needs, control, sink);
    else if (groups == 1) pixels += walk_triangle<true, false>(setup, attributes, needs, control, sink);
    else pixels += walk_triangle<true, true>(setup, attributes, needs, control, sink);
    benchmark::DoNotOptimize(sink.data());
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_pixel"] = benchmark::Counter(static_cast<double>(pixels), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(span_walk)->ArgNames({"span_log2", "groups"})->ArgsProduct({{0, 2, 4, 6}, {0, 1, 2}});
