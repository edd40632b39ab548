// The span walk (span.hpp): one triangle's rows, per span length, for a pass
// that interpolates depth only, depth + uv, or depth + uv + one projector.
// Reported per covered pixel.
#include <benchmark/benchmark.h>

#include <vector>

#include "benchmark_triangle.hpp"
#include "spanlight/features.hpp"

namespace {

using R = spanlight::TableReciprocal<8, 1>;

void span_walk(benchmark::State& state) {
  const int span_log2 = static_cast<int>(state.range(0));
  const int groups = static_cast<int>(state.range(1));  // 0 depth, 1 + uv, 2 + uv + projector
  const spanlight::TriangleSetup setup = benchmarks::floor_setup();
  const spanlight::TriangleAttributes<1> attributes = benchmarks::floor_attributes(setup);
  const spanlight::SpanNeeds needs{groups >= 1, 0, groups >= 2 ? 1 : 0};
  const std::uint16_t projector_texels[1] = {256};
  const spanlight::SpanControl control{span_log2, 3, 16, projector_texels};
  std::vector<std::int32_t> sink(benchmarks::width * benchmarks::height);
  std::int64_t pixels = 0;
  for (auto _ : state) {
    spanlight::TriangleSetup t = setup;  // rasterize_rows steps the edges
    spanlight::rasterize_rows(t, benchmarks::width, [&](std::int32_t row, std::int32_t c0, std::int32_t c1) {
      spanlight::walk_span<1, R>(t, attributes, needs, control, c0, c1, [&](std::int32_t column, const spanlight::PointValues<1>& v) {
        sink[static_cast<std::size_t>(row * benchmarks::width + column)] = v.z + v.u + v.s[0];
        ++pixels;
      });
    });
    benchmark::DoNotOptimize(sink.data());
    benchmark::ClobberMemory();
  }
  state.counters["ns_per_pixel"] = benchmark::Counter(static_cast<double>(pixels), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK(span_walk)->ArgNames({"span_log2", "groups"})->ArgsProduct({{0, 2, 4, 5}, {0, 1, 2}});
