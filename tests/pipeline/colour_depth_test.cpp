// 4_pixel/colour.hpp and depth.hpp against scalar references, exhaustively
// over every 8-bit level: the lane tricks (two channels in one word) must give
// each channel's scalar answer, and the formats must round to nearest.
#include <catch2/catch.hpp>

#include <cstdint>
#include <random>

#include "spanlight/4_pixel/colour.hpp"
#include "spanlight/4_pixel/depth.hpp"

using spanlight::Colour;

namespace {

// round(c * levels / 255), exact in integers (ties cannot occur: 255 is odd and levels < 255).
constexpr std::uint32_t rounded(std::uint32_t c, std::uint32_t levels) { return (2 * c * levels + 255) / 510; }
// round(a * b / 255), exact (ties cannot occur).
constexpr std::uint32_t mul255_reference(std::uint32_t a, std::uint32_t b) { return (2 * a * b + 255) / 510; }

}  // namespace

TEST_CASE("RGB565 packs each channel to its nearest 5 or 6 bit level and expands by bit replication", "[colour]") {
  int wrong_pack = 0, wrong_unpack = 0, wrong_be = 0, wrong_888 = 0;
  for (std::uint32_t r = 0; r < 256; ++r) {
    for (std::uint32_t x = 0; x < 256; ++x) {
      // Red and blue share a lane word: every pair; green alongside with x as well.
      const Colour c = spanlight::colour_of(r, x, 255 - x);
      const std::uint32_t b = 255 - x;
      const std::uint32_t expected = (rounded(r, 31) << 11) | (rounded(x, 63) << 5) | rounded(b, 31);
      const std::uint32_t packed = spanlight::pack565(c) & 0xFFFFu;
      wrong_pack += packed != expected;
      const Colour back = spanlight::unpack565(packed);
      const std::uint32_t r5 = expected >> 11, g6 = (expected >> 5) & 63u, b5 = expected & 31u;
      wrong_unpack += !(back == spanlight::colour_of((r5 << 3) | (r5 >> 2), (g6 << 2) | (g6 >> 4), (b5 << 3) | (b5 >> 2)));
      // The stored formats: RGB565 and its byte-swapped twin load what quantize says; RGB888 is exact.
      std::uint16_t word = 0, word_be = 0;
      spanlight::ColorTraits<spanlight::PixelFormat::rgb565>::store(&word, c);
      spanlight::ColorTraits<spanlight::PixelFormat::rgb565_be>::store(&word_be, c);
      wrong_be += word != expected || word_be != static_cast<std::uint16_t>(((expected & 0xFFu) << 8) | (expected >> 8)) ||
                  !(spanlight::ColorTraits<spanlight::PixelFormat::rgb565_be>::load(&word_be) == back) ||
                  !(spanlight::ColorTraits<spanlight::PixelFormat::rgb565>::quantize(c) == back);
      std::uint8_t bytes[3] = {};
      spanlight::ColorTraits<spanlight::PixelFormat::rgb888>::store(bytes, c);
      wrong_888 += bytes[0] != r || bytes[1] != x || bytes[2] != b ||
                   !(spanlight::ColorTraits<spanlight::PixelFormat::rgb888>::load(bytes) == c);
    }
  }
  CHECK(wrong_pack == 0);
  CHECK(wrong_unpack == 0);
  CHECK(wrong_be == 0);
  CHECK(wrong_888 == 0);
}

TEST_CASE("modulate is round(light * surface / 255) per channel and add_light saturates at 255", "[colour]") {
  int wrong_mul = 0, wrong_modulate = 0, wrong_add = 0;
  for (std::uint32_t a = 0; a < 256; ++a) {
    for (std::uint32_t b = 0; b < 256; ++b) {
      wrong_mul += spanlight::mul255(a, b) != mul255_reference(a, b);
      // Red and blue in their lanes with different operands, green on its own.
      const Colour light = spanlight::colour_of(a, b, 255 - a), surface = spanlight::colour_of(b, a, 255 - b);
      const Colour m = spanlight::modulate(light, surface);
      wrong_modulate += !(m == spanlight::colour_of(mul255_reference(a, b), mul255_reference(b, a),
                                                    mul255_reference(255 - a, 255 - b)));
      const Colour s = spanlight::add_light(light, surface);
      auto sat = [](std::uint32_t x, std::uint32_t y) { return x + y > 255 ? 255u : x + y; };
      wrong_add += !(s == spanlight::colour_of(sat(a, b), sat(b, a), sat(255 - a, 255 - b)));
    }
  }
  CHECK(wrong_mul == 0);
  CHECK(wrong_modulate == 0);
  CHECK(wrong_add == 0);
}

TEST_CASE("DepthFormat keeps the top depth bits, and no stepped depth up to z_limit stores the clear value",
          "[depth]") {
  for (const int bits : {16, 24}) {
    INFO(bits << "-bit depth");
    const spanlight::DepthFormat<> f(bits);
    const std::uint32_t clear = spanlight::depth_clear(bits);
    CHECK(f.clear == clear);
    CHECK(clear == (bits == 16 ? 0xFFFFu : 0xFFFFFFu));
    // z_limit is the deepest Q0.32 depth that stores below the clear value: one more stores clear.
    CHECK(f.store(f.z_limit) == clear - 1);
    CHECK(f.store(f.z_limit + 1) == clear);
    CHECK(f.store_clamped(0xFFFFFFFFu) == clear - 1);
    CHECK(f.store_clamped(f.z_limit) == clear - 1);
    CHECK(f.store(0) == 0);
    // The baked (compile-time) format stores the same as the run-time one.
    std::independent_bits_engine<std::mt19937, 32, std::uint32_t> random(0xdeb7);  // 32-bit results: the same sequence
    int differ = 0;
    for (int n = 0; n < 100000; ++n) {
      const std::uint32_t z = random();
      const std::uint32_t baked = bits == 16 ? spanlight::DepthFormat<16>(16).store(z) : spanlight::DepthFormat<24>(24).store(z);
      differ += baked != f.store(z) || f.store(z) != z >> (32 - bits);
    }
    CHECK(differ == 0);
  }
}

TEST_CASE("the tie mask claims a pixel once until cleared, one bit a pixel", "[depth]") {
  CHECK(spanlight::tie_mask_bytes(0) == 0);
  CHECK(spanlight::tie_mask_bytes(1) == 1);
  CHECK(spanlight::tie_mask_bytes(8) == 1);
  CHECK(spanlight::tie_mask_bytes(9) == 2);
  std::uint8_t mask[3] = {0, 0, 0};
  for (std::uint32_t i = 0; i < 24; ++i) CHECK(spanlight::claim_pixel(mask, i));
  for (std::uint32_t i = 0; i < 24; ++i) CHECK_FALSE(spanlight::claim_pixel(mask, i));
  CHECK(mask[0] == 0xFF);
  CHECK(mask[2] == 0xFF);
}
