// Texture sampling (sample.hpp): nearest and bilinear fetches from a 128x128
// RGB texture along a slanted line of coordinates inside it, per wrap mode.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "spanlight/sample.hpp"

namespace {

struct Texture {
  std::vector<std::uint8_t> texels = std::vector<std::uint8_t>(128 * 128 * 3);
  spanlight::TextureData data{};
  Texture(spanlight::Filter filter, spanlight::Wrap wrap) {
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = static_cast<std::uint8_t>(i * 37u);
    data = {texels.data(), 128, 128, filter, wrap};
  }
};

template <bool Bilinear>
void sample(benchmark::State& state) {
  const auto wrap = static_cast<spanlight::Wrap>(state.range(0));
  const Texture texture(Bilinear ? spanlight::Filter::bilinear : spanlight::Filter::nearest, wrap);
  constexpr int frac = 16;
  for (auto _ : state) {
    std::uint32_t sum = 0;
    std::int32_t u = 3 << 15, v = 5 << 15;
    for (int i = 0; i < 1024; ++i) {
      const spanlight::Rgb8 c = spanlight::sample<Bilinear>(texture.data, u, v, frac, wrap);
      sum += c.r + c.g + c.b;
      u += 45000;  // about 0.7 texel a step, kept inside the texture so border does not short-cut
      v += 20000;
      if (u > (120 << 16)) u -= 112 << 16;
      if (v > (120 << 16)) v -= 112 << 16;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * 1024);
}

}  // namespace

BENCHMARK(sample<false>)->ArgName("wrap")->DenseRange(0, 2);
BENCHMARK(sample<true>)->ArgName("wrap")->DenseRange(0, 2);
