// blend_check: pipeline/.../4_pixel/texture.hpp's bilinear blend, rounded (bilinear_colour) and
// unrounded (bilinear_texel16), against the scalar sums S = sum c_ij w_ij of each channel, for
// every weight pair (fx, fy) in [0, 255]^2 on texel sets at the lanes' limits and at random. On
// Cortex-M4 and M7 the blend is the dual multiply-add form (smlad, pkhbt, pkhtb) that the host
// never runs: frames equal to the host's cover it only as far as the scenes' texels go. Logs the
// count of wrong blends and returns 1 if there is one.
#include <cstdint>

#include "hal/hal.hpp"
#include "hal/log_line.hpp"
#include "spanlight/4_pixel/texture.hpp"

namespace {

std::uint32_t wrong = 0;

void check(const std::uint32_t (&t)[4]) {
  for (std::uint32_t fy = 0; fy < 256; ++fy) {
    for (std::uint32_t fx = 0; fx < 256; ++fx) {
      const spanlight::Taps taps{t[0], t[1], t[2], t[3], fx, fy};
      const std::uint32_t w[4] = {(256 - fx) * (256 - fy), fx * (256 - fy), (256 - fx) * fy, fx * fy};
      std::uint32_t sum[3] = {0, 0, 0};  // red, green, blue
      for (int k = 0; k < 4; ++k)
        for (int c = 0; c < 3; ++c) sum[c] += ((t[k] >> (16 - 8 * c)) & 255u) * w[k];
      const spanlight::Colour rounded = spanlight::bilinear_colour(taps);
      const spanlight::Texel16 raw = spanlight::bilinear_texel16(taps);
      auto round = [](std::uint32_t s) { return (s + 32768u) >> 16; };
      wrong += rounded.rb != ((round(sum[0]) << 16) | round(sum[2])) || rounded.g != round(sum[1]) || raw.r != sum[0] ||
               raw.g != sum[1] || raw.b != sum[2];
    }
  }
}

}  // namespace

int spanlight::hal::app_main(Args /*args*/) {
  std::uint32_t sets[12][4] = {{0x00FFFFFFu, 0x00FFFFFFu, 0x00FFFFFFu, 0x00FFFFFFu},
                               {0, 0, 0, 0},
                               {0x00FFFFFFu, 0, 0, 0},
                               {0, 0, 0, 0x00FFFFFFu},
                               {0x00FF00FFu, 0x0000FF00u, 0x00FF00FFu, 0x0000FF00u},
                               {0, 0x00FFFFFFu, 0x00FFFFFFu, 0}};
  std::uint32_t state = 0x9E3779B9u;  // xorshift32
  for (int n = 6; n < 12; ++n) {
    for (std::uint32_t& texel : sets[n]) {
      state ^= state << 13;
      state ^= state >> 17;
      state ^= state << 5;
      texel = state & 0x00FFFFFFu;
    }
  }
  for (const auto& t : sets) check(t);
  log_line(LogLine() << "blend_check: " << 12u * 65536u << " blends, " << wrong << " wrong");
  return wrong == 0 ? 0 : 1;
}
