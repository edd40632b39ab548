// Per-triangle work before any pixel: the perspective divide of three
// vertices (1_vertex/project.hpp) and the triangle setup (2_triangle/setup.hpp).
#include <benchmark/benchmark.h>

#include "benchmark_triangle.hpp"

namespace {

void project_and_setup(benchmark::State& state) {
  for (auto _ : state) {
    const spanlight::ScreenVertex screen[3] = {spanlight::project(benchmarks::corners[0], benchmarks::width, benchmarks::height),
                                               spanlight::project(benchmarks::corners[1], benchmarks::width, benchmarks::height),
                                               spanlight::project(benchmarks::corners[2], benchmarks::width, benchmarks::height)};
    spanlight::TriangleSetup setup{};
    const bool visible = spanlight::setup_triangle(screen, spanlight::Cull::none, benchmarks::height, setup);
    benchmark::DoNotOptimize(visible);
    benchmark::DoNotOptimize(setup);
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

BENCHMARK(project_and_setup);
