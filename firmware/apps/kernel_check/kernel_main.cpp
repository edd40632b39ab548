// kernel_check: the fused pass's run drawn twice over the same buffers, once by the kernel as
// firmware builds it (on Cortex-M0+ the Thumb-1 loop of thumb1_run.hpp, for RGB565, 16-bit depth
// and a bilinear repeating texture) and once by the C++ loop (a hooks type that watches pixels
// keeps the kernel off the assembly), and compares depth and colour. The runs are random: texture
// sizes from 2x2 to 64x32 with random texels, any u, v and z with their steps, ambient white or
// not, depths that hide some pixels. On the other cores both are the C++ loop. Logs the count of
// differing pixels and returns 1 if there is one.
#include <array>
#include <cstdint>

#include "hal/hal.hpp"
#include "hal/log_line.hpp"
#include "spanlight/5_frame/passes.hpp"

namespace {

using namespace spanlight;

constexpr Features features{.max_projectors = 0, .shadows = false, .pcf = false, .nearest = false, .bilinear = true,
                            .clamped = false, .tinted = false, .trilinear = false, .falloff = false, .facing = false,
                            .format = PixelFormat::rgb565, .fused = true, .multipass = false, .table_bits = 8, .newton = 1,
                            .depth_bits = 16, .repeat_sizes = {}, .any_repeat_size = true};
using Depth = std::uint16_t;

struct Unwatched : NoHooks {};
struct Watching : NoHooks {  // its own touched: the kernel takes the C++ loop
  std::uint32_t pixels = 0;
  void touched(Pass, std::uint32_t) { ++pixels; }
};
static_assert(!sees_pixels<Unwatched>() && sees_pixels<Watching>());

constexpr int max_log2_width = 6, max_log2_height = 5, max_run = 96;
std::array<std::uint32_t, framed_texel_count(1u << max_log2_width, 1u << max_log2_height)> texels;
std::array<Depth, max_run> depth_fast, depth_plain;
std::array<std::uint16_t, max_run> colour_fast, colour_plain;

std::uint32_t state = 0x2545F491u;  // xorshift32
std::uint32_t next() {
  state ^= state << 13;
  state ^= state >> 17;
  state ^= state << 5;
  return state;
}

template <typename Hooks>
void draw(const ObjectData& object, const TextureData& texture, Colour ambient, const PixelRun<0>& run, std::int32_t count,
          Depth* depth, std::uint16_t* colour, Hooks& hooks) {
  FusedKernel<features, Depth, Hooks> kernel{{colour, depth, nullptr}, &texture, nullptr, 0, ambient,
                                             DepthFormat<features.depth_bits>(features.depth_bits), hooks};
  kernel.object(object);
  kernel.run(0, count, run);
}

}  // namespace

int spanlight::hal::app_main(Args /*args*/) {
  std::uint32_t runs = 0, pixels = 0, drawn = 0, differing = 0;
  for (int n = 0; n < 3000; ++n) {
    const int wl = 1 + static_cast<int>(next() % max_log2_width), hl = 1 + static_cast<int>(next() % max_log2_height);
    const std::uint16_t width = static_cast<std::uint16_t>(1u << wl), height = static_cast<std::uint16_t>(1u << hl);
    const std::uint16_t stride = static_cast<std::uint16_t>(width + 2 * texture_frame);
    for (std::uint32_t k = 0; k < framed_texel_count(width, height); ++k) texels[k] = next() & 0x00FFFFFFu;
    const TextureLevel level{texels.data() + stride + texture_frame, width, height, stride};
    const TextureData texture{&level, 1, Filter::bilinear, Wrap::repeat};
    ObjectData object{};
    object.texture = 0;
    object.uv_frac_bits = 8;
    object.color[0] = object.color[1] = object.color[2] = 255;
    // The ambient as the pass holds it, quantised to RGB565; white in one run of four.
    const std::uint32_t a = next();
    const Colour ambient = n % 4 == 0 ? white : ColorTraits<PixelFormat::rgb565>::quantize(colour_of(a & 0x00FFFFFFu));
    PixelRun<0> run{};
    run.z = next();
    run.dz = static_cast<std::int32_t>(next()) >> (8 + next() % 16);
    // Steps from a texel per pixel down to a small fraction, their curves smaller still.
    auto stepped = [] {
      const std::uint32_t value = next();
      const auto step = static_cast<std::uint32_t>(static_cast<std::int32_t>(next()) >> (next() % 24));
      const auto curve = static_cast<std::uint32_t>(static_cast<std::int32_t>(next()) >> (8 + next() % 24));
      return Stepped{value, step, curve};
    };
    run.u = stepped();
    run.v = stepped();
    const auto count = static_cast<std::int32_t>(1 + next() % max_run);
    for (std::int32_t k = 0; k < count; ++k) {
      depth_fast[k] = depth_plain[k] = static_cast<Depth>(next());
      colour_fast[k] = colour_plain[k] = static_cast<std::uint16_t>(next());
    }
    Unwatched fast;
    Watching plain;
    draw(object, texture, ambient, run, count, depth_fast.data(), colour_fast.data(), fast);
    draw(object, texture, ambient, run, count, depth_plain.data(), colour_plain.data(), plain);
    for (std::int32_t k = 0; k < count; ++k) differing += depth_fast[k] != depth_plain[k] || colour_fast[k] != colour_plain[k];
    ++runs;
    pixels += static_cast<std::uint32_t>(count);
    drawn += plain.pixels;
  }
  log_line(LogLine() << "kernel_check: " << runs << " runs, " << pixels << " pixels, " << drawn << " drawn, " << differing
                     << " differing");
  return differing == 0 && drawn > 0 ? 0 : 1;
}
