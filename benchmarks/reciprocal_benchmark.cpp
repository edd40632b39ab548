// The reciprocal (fixedpoint/reciprocal.hpp) per table size and Newton steps,
// on 4096 inputs spread over the 32-bit range.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <random>

#include "fixedpoint/reciprocal.hpp"

namespace {

const std::array<std::uint32_t, 4096>& inputs() {
  static const std::array<std::uint32_t, 4096> values = [] {
    std::array<std::uint32_t, 4096> v{};
    std::mt19937 rng(7);
    for (std::uint32_t& x : v) x = static_cast<std::uint32_t>(rng()) | 1u;
    return v;
  }();
  return values;
}

template <int TableBits, int NewtonSteps>
void reciprocal(benchmark::State& state) {
  const auto& in = inputs();
  for (auto _ : state) {
    std::uint32_t sum = 0;
    for (std::uint32_t d : in) sum += fixedpoint::reciprocal<TableBits, NewtonSteps>(d).mantissa;
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(in.size()));
}

}  // namespace

BENCHMARK(reciprocal<6, 0>);
BENCHMARK(reciprocal<6, 1>);
BENCHMARK(reciprocal<8, 0>);
BENCHMARK(reciprocal<8, 1>);
BENCHMARK(reciprocal<8, 2>);
BENCHMARK(reciprocal<10, 1>);
BENCHMARK(reciprocal<12, 0>);
BENCHMARK(reciprocal<12, 1>);
