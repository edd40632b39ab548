// kernel_check: the fused pass's run drawn twice over the same buffers, once by the kernel as
// firmware builds it (on Cortex-M0+ the Thumb-1 loops of thumb1_run.hpp, for a bilinear or
// nearest repeating texture) and once by the C++ loop (a hooks type that watches pixels keeps the kernel off the
// assembly), and compares depth and colour, for 16- and 24-bit depth and RGB565 and RGB888. The
// runs are random: texture sizes from 2x2 to 64x32 with random texels, any u, v and z with their
// steps, ambient white or not, depths that hide some pixels. On the other cores both are the C++
// loop. Logs the count of differing pixels and returns 1 if there is one.
#include <array>
#include <cstdint>
#include <type_traits>

#include "hal/hal.hpp"
#include "hal/log_line.hpp"
#include "spanlight/5_frame/passes.hpp"

namespace {

using namespace spanlight;

template <int DepthBits, PixelFormat Format>
constexpr Features features{.max_projectors = 0, .shadows = false, .pcf = false, .nearest = true, .bilinear = true,
                            .clamped = false, .tinted = false, .trilinear = false, .falloff = false, .facing = false, .closed_solids = false,
                            .format = Format, .fused = true, .multipass = false, .table_bits = 8, .newton = 1,
                            .depth_bits = DepthBits, .repeat_sizes = {}, .any_repeat_size = true};

struct Unwatched : NoHooks {};
struct Watching : NoHooks {  // its own touched: the kernel takes the C++ loop
  std::uint32_t pixels = 0;
  void touched(Pass, std::uint32_t) { ++pixels; }
};
static_assert(!sees_pixels<Unwatched>() && sees_pixels<Watching>());

constexpr int max_log2_width = 6, max_log2_height = 5, max_run = 96;
std::array<std::uint32_t, framed_texel_count(1u << max_log2_width, 1u << max_log2_height)> texels;

std::uint32_t state = 0x2545F491u;  // xorshift32
std::uint32_t next() {
  state ^= state << 13;
  state ^= state >> 17;
  state ^= state << 5;
  return state;
}

struct Tally {
  std::uint32_t runs = 0, pixels = 0, drawn = 0, differing = 0;
};

// `runs` random runs drawn both ways with DepthBits in its storage, Format and the filter.
template <int DepthBits, PixelFormat Format, Filter Filtered>
void check(int runs, Tally& tally) {
  constexpr Features f = features<DepthBits, Format>;
  using Depth = std::conditional_t<DepthBits == 16, std::uint16_t, std::uint32_t>;
  using Color = ColorTraits<Format>;
  using Storage = typename Color::Storage;
  std::array<Depth, max_run> depth_fast, depth_plain;
  std::array<Storage, max_run * Color::per_pixel> colour_fast, colour_plain;
  for (int n = 0; n < runs; ++n) {
    const int wl = 1 + static_cast<int>(next() % max_log2_width), hl = 1 + static_cast<int>(next() % max_log2_height);
    const std::uint16_t width = static_cast<std::uint16_t>(1u << wl), height = static_cast<std::uint16_t>(1u << hl);
    const std::uint16_t stride = static_cast<std::uint16_t>(width + 2 * texture_frame);
    for (std::uint32_t k = 0; k < framed_texel_count(width, height); ++k) texels[k] = next() & 0x00FFFFFFu;
    const TextureLevel level{texels.data() + stride + texture_frame, width, height, stride};
    const TextureData texture{&level, 1, Filtered, Wrap::repeat};
    ObjectData object{};
    object.texture = 0;
    object.uv_frac_bits = 8;
    object.color[0] = object.color[1] = object.color[2] = 255;
    // The ambient as the pass holds it, quantised to the format; white in one run of four.
    const Colour ambient = n % 4 == 0 ? white : Color::quantize(colour_of(next() & 0x00FFFFFFu));
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
    // Stored depths around the run's (24-bit ones below 2^24, as the pass stores them).
    for (std::int32_t k = 0; k < count; ++k) depth_fast[k] = depth_plain[k] = static_cast<Depth>(next() >> (32 - DepthBits));
    for (std::int32_t k = 0; k < count * Color::per_pixel; ++k) colour_fast[k] = colour_plain[k] = static_cast<Storage>(next());
    Unwatched fast;
    Watching plain;
    auto draw = [&](Depth* depth, Storage* colour, auto& hooks) {
      FusedKernel<f, Depth, std::remove_reference_t<decltype(hooks)>> kernel{
          {colour, depth, nullptr}, &texture, nullptr, 0, ambient, DepthFormat<f.depth_bits>(f.depth_bits), hooks};
      kernel.object(object);
      kernel.run(0, count, run);
    };
    draw(depth_fast.data(), colour_fast.data(), fast);
    draw(depth_plain.data(), colour_plain.data(), plain);
    for (std::int32_t k = 0; k < count; ++k) {
      bool same = depth_fast[k] == depth_plain[k];
      for (int b = 0; b < Color::per_pixel; ++b) same = same && colour_fast[k * Color::per_pixel + b] == colour_plain[k * Color::per_pixel + b];
      tally.differing += !same;
    }
    ++tally.runs;
    tally.pixels += static_cast<std::uint32_t>(count);
    tally.drawn += plain.pixels;
  }
}

}  // namespace

int spanlight::hal::app_main(Args /*args*/) {
  Tally tally;
  for (const Filter filter : {Filter::bilinear, Filter::nearest}) {
    auto each_storage = [&]<Filter Filtered>() {
      check<16, PixelFormat::rgb565, Filtered>(500, tally);
      check<24, PixelFormat::rgb565, Filtered>(500, tally);
      check<16, PixelFormat::rgb888, Filtered>(500, tally);
      check<24, PixelFormat::rgb888, Filtered>(500, tally);
    };
    if (filter == Filter::bilinear) each_storage.template operator()<Filter::bilinear>();
    else each_storage.template operator()<Filter::nearest>();
  }
  log_line(LogLine() << "kernel_check: " << tally.runs << " runs, " << tally.pixels << " pixels, " << tally.drawn << " drawn, "
                     << tally.differing << " differing");
  return tally.differing == 0 && tally.drawn > 0 ? 0 : 1;
}
