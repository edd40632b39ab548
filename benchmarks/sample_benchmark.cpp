// Texture sampling (4_pixel/texture.hpp): nearest and bilinear fetches from a
// 128x128 texture in the sampler's layout along a slanted line of coordinates
// inside it, per wrap mode (repeat: coordinates as a fraction of the size).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "spanlight/4_pixel/texture.hpp"

namespace {

struct Texture {
  static constexpr int size = 128, stride = size + 2 * spanlight::texture_frame;
  std::vector<std::uint32_t> texels = std::vector<std::uint32_t>(spanlight::framed_texel_count(size, size));
  spanlight::TexelGrid grid{};
  Texture() {
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = static_cast<std::uint32_t>(i * 2654435761u) & 0x00FFFFFFu;
    const spanlight::TextureLevel level{texels.data() + stride + 1, size, size, stride};
    grid = spanlight::texel_grid(level, 16);
  }
};

template <bool Bilinear>
void sample(benchmark::State& state) {
  const auto wrap = static_cast<spanlight::Wrap>(state.range(0));
  const Texture texture;
  const spanlight::TexelGrid& g = texture.grid;
  for (auto _ : state) {
    std::uint32_t sum = 0;
    std::int32_t u = 3 << 15, v = 5 << 15;  // texels * 2^16
    for (int i = 0; i < 1024; ++i) {
      spanlight::Colour c{};
      // Repeat steps the same coordinate as a fraction of the size (128 texels: texels * 2^16 << 9).
      const auto ru = static_cast<std::uint32_t>(u) << 9, rv = static_cast<std::uint32_t>(v) << 9;
      if constexpr (Bilinear) {
        if (wrap == spanlight::Wrap::repeat) c = spanlight::bilinear_repeat(g, ru, rv);
        else if (wrap == spanlight::Wrap::clamp) c = spanlight::bilinear_clamp(g, u, v);
        else c = spanlight::bilinear_border(g, u, v);
      } else {
        if (wrap == spanlight::Wrap::repeat) c = spanlight::nearest_repeat(g, ru, rv);
        else if (wrap == spanlight::Wrap::clamp) c = spanlight::nearest<spanlight::Wrap::clamp>(g, u, v);
        else c = spanlight::nearest<spanlight::Wrap::border>(g, u, v);
      }
      sum += c.rb + c.g;
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
