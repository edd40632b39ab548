// The trilinear sampler (4_pixel/mipmap.hpp) against a scalar reference written
// from the spec: level k read bilinearly at the same (u, v) with the texture's
// wrap (texel centres at half-integers of level k), 8-bit weights as the
// pipeline keeps them, two levels mixed by f/256 and rounded once. The weights
// are integers, so the reference is exact and the sampler must equal it.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>
#include <vector>

#include "spanlight/4_pixel/mipmap.hpp"

using namespace spanlight;

namespace {

// A texture of `levels` levels, level 0 of w x h, each level framed for `wrap`, texels random.
struct Chain {
  std::vector<std::vector<std::uint32_t>> images;  // unframed, rows from the bottom
  std::vector<std::vector<std::uint32_t>> framed;
  std::vector<TextureLevel> levels;
  TextureData data{};
};

Chain make_chain(int w, int h, Wrap wrap, std::mt19937& rng) {
  Chain c;
  for (int lw = w, lh = h;; lw = lw > 1 ? lw / 2 : 1, lh = lh > 1 ? lh / 2 : 1) {
    std::vector<std::uint32_t> image(static_cast<std::size_t>(lw * lh));
    for (auto& t : image) t = rng() & 0xFFFFFFu;
    c.images.push_back(image);
    const int stride = lw + 2;
    std::vector<std::uint32_t> framed(static_cast<std::size_t>(stride * (lh + 2)));
    for (int y = -1; y <= lh; ++y)
      for (int x = -1; x <= lw; ++x) {
        int sx = x, sy = y;
        std::uint32_t value = 0;
        if (wrap == Wrap::repeat) {
          sx = (x + lw) % lw;
          sy = (y + lh) % lh;
          value = image[static_cast<std::size_t>(sy * lw + sx)];
        } else if (wrap == Wrap::clamp) {
          sx = x < 0 ? 0 : (x >= lw ? lw - 1 : x);
          sy = y < 0 ? 0 : (y >= lh ? lh - 1 : y);
          value = image[static_cast<std::size_t>(sy * lw + sx)];
        } else if (x >= 0 && y >= 0 && x < lw && y < lh) {
          value = image[static_cast<std::size_t>(y * lw + x)];
        }
        framed[static_cast<std::size_t>((y + 1) * stride + x + 1)] = value;
      }
    c.framed.push_back(framed);
    if (lw == 1 && lh == 1) break;
  }
  for (std::size_t k = 0; k < c.framed.size(); ++k) {
    const int lw = static_cast<int>(std::max(1, w >> k)), lh = static_cast<int>(std::max(1, h >> k));
    c.levels.push_back({c.framed[k].data() + (lw + 2) + 1, static_cast<std::uint16_t>(lw), static_cast<std::uint16_t>(lh),
                        static_cast<std::uint16_t>(lw + 2)});
  }
  c.data = {c.levels.data(), static_cast<std::uint8_t>(c.levels.size()), Filter::trilinear, wrap};
  return c;
}

// The exact sum of level k's bilinear sample at (X, Y) in level-0 texels (Q.16), 8-bit weights, times 2^16.
std::uint64_t level_sum(const Chain& c, int k, Wrap wrap, std::int64_t x16, std::int64_t y16, int channel) {
  const int lw = c.levels[k].width, lh = c.levels[k].height;
  // Level-k texel coordinate, centre at half-integers: X / 2^k - 1/2, with 8 fraction bits (truncated as the pipeline's are).
  const std::int64_t xk = ((x16 >> k) - (1 << 15)) >> 8, yk = ((y16 >> k) - (1 << 15)) >> 8;
  std::int64_t x0 = xk >> 8, y0 = yk >> 8, fx = xk & 255, fy = yk & 255;
  auto texel = [&](std::int64_t x, std::int64_t y) -> std::uint64_t {
    if (wrap == Wrap::repeat) {
      x = ((x % lw) + lw) % lw;
      y = ((y % lh) + lh) % lh;
    } else if (wrap == Wrap::clamp) {
      x = x < 0 ? 0 : (x >= lw ? lw - 1 : x);
      y = y < 0 ? 0 : (y >= lh ? lh - 1 : y);
    } else if (x < 0 || y < 0 || x >= lw || y >= lh) {
      return 0;
    }
    return (c.images[k][static_cast<std::size_t>(y * lw + x)] >> (8 * (2 - channel))) & 255u;
  };
  if (wrap == Wrap::clamp) {  // beyond the outer centres the edge texel alone
    if (xk < 0) x0 = 0, fx = 0;
    if (xk > (lw - 1) * 256) x0 = lw - 1, fx = 0;
    if (yk < 0) y0 = 0, fy = 0;
    if (yk > (lh - 1) * 256) y0 = lh - 1, fy = 0;
  }
  return texel(x0, y0) * static_cast<std::uint64_t>((256 - fx) * (256 - fy)) + texel(x0 + 1, y0) * static_cast<std::uint64_t>(fx * (256 - fy)) +
         texel(x0, y0 + 1) * static_cast<std::uint64_t>((256 - fx) * fy) + texel(x0 + 1, y0 + 1) * static_cast<std::uint64_t>(fx * fy);
}

}  // namespace

TEST_CASE("the trilinear sampler mixes two bilinear levels exactly as the spec's reference", "[mipmap]") {
  std::mt19937 rng(0x7e11);
  for (const Wrap wrap : {Wrap::repeat, Wrap::clamp, Wrap::border}) {
    for (const auto& [w, h] : {std::pair{16, 16}, std::pair{32, 4}, std::pair{2, 64}}) {
      const Chain c = make_chain(w, h, wrap, rng);
      const int frac = 12;
      TexelGrid g0 = texel_grid(c.levels[0], frac);
      int checked = 0;
      for (int n = 0; n < 4000; ++n) {
        // A point in level-0 texels, Q.16, kept on the 8-bit grid of the coarsest level read (so both sides truncate alike).
        const int last = c.data.level_count - 1;
        const std::int32_t lod = static_cast<std::int32_t>(rng() % static_cast<unsigned>((last + 2) * 256)) - 256;
        std::int64_t x16 = static_cast<std::int64_t>(rng() % static_cast<unsigned>(w * 3 << 16)) - (w << 16);
        std::int64_t y16 = static_cast<std::int64_t>(rng() % static_cast<unsigned>(h * 3 << 16)) - (h << 16);
        x16 &= ~std::int64_t{(1 << (8 + last)) - 1};
        y16 &= ~std::int64_t{(1 << (8 + last)) - 1};
        if (wrap == Wrap::repeat) {  // the walk's scale: fraction of the size in 32 bits
          x16 = ((x16 % (w << 16)) + (w << 16)) % (w << 16);
          y16 = ((y16 % (h << 16)) + (h << 16)) % (h << 16);
        }
        // The walk's coordinates: bilinear's half texel back, in its scale.
        std::uint32_t x, y;
        if (wrap == Wrap::repeat) {
          x = static_cast<std::uint32_t>((x16 << (g0.x_shift - 16)) - (std::int64_t{1} << (g0.x_shift - 1)));
          y = static_cast<std::uint32_t>((y16 << (g0.y_shift - 16)) - (std::int64_t{1} << (g0.y_shift - 1)));
        } else {
          x = static_cast<std::uint32_t>((x16 >> (16 - frac)) - (1 << (frac - 1)));
          y = static_cast<std::uint32_t>((y16 >> (16 - frac)) - (1 << (frac - 1)));
        }
        std::int32_t one = 1;
        const RunLevel level = run_level(lod << 8, 0, last, one);
        Colour got{};
        auto take = [&](const auto& sample) { got = sample(x, y, 0); };
        if (wrap == Wrap::repeat) with_run_levels<Wrap::repeat>(c.data, g0, level, take);
        if (wrap == Wrap::clamp) with_run_levels<Wrap::clamp>(c.data, g0, level, take);
        if (wrap == Wrap::border) with_run_levels<Wrap::border>(c.data, g0, level, take);
        const std::int32_t d = lod <= 0 ? 0 : std::min(lod, last * 256);
        const int k = d >> 8, k1 = std::min(k + 1, last);
        const std::uint64_t f = static_cast<std::uint64_t>(d & 255);
        std::uint32_t want[3];
        for (int ch = 0; ch < 3; ++ch) {
          const std::uint64_t mixed = (256 - f) * level_sum(c, k, wrap, x16, y16, ch) + f * level_sum(c, k1, wrap, x16, y16, ch);
          want[ch] = static_cast<std::uint32_t>((mixed + (1u << 23)) >> 24);
        }
        INFO("wrap " << int(wrap) << " size " << w << "x" << h << " lod " << lod << " at " << x16 << ", " << y16 << " (Q.16)");
        REQUIRE(red(got) == want[0]);
        REQUIRE(green(got) == want[1]);
        REQUIRE(blue(got) == want[2]);
        ++checked;
      }
      CHECK(checked == 4000);
    }
  }
}
