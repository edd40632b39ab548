// sweep_bench: the cost side of `spanlight sweep` on target. One ELF per baked
// scene holds the scene's eight reciprocal instantiations (table bits 6, 8, 10,
// 12 x Newton 0, 1, chosen through spanlight::dispatch); span, tolerance, depth
// bits and passes are run-time knobs, and the texture filter may be forced. A
// run renders one frame with the knobs on its command line inside the measured
// region (with --per-pass, one region per pass, bracketed by render_frame's
// hooks), logs the frame hash, and exits. Knobs not given are the baked ones; the
// format must be the baked one.
//   sweep_bench_<scene>.elf --span 16 --tolerance 3 --table-bits 8 --newton 1
//                           --depth-bits 24 --passes fused [--filter scene] [--per-pass]
#include <array>

#include "baked_frame.hpp"
#include "bench_request.hpp"
#include "hal/log_line.hpp"
#include "spanlight/dispatch.hpp"
#include "spanlight/render.hpp"

namespace {

using namespace spanlight;

// The baked scene's Features with both filters (a forced filter works on any
// scene), both pass plans, and depth bits and reciprocal at run time. Depth is
// stored in uint32 for both depth settings: the values are the same.
constexpr Features bench_features() {
  Features f = baked::features;
  f.nearest = f.bilinear = true;
  f.fused = f.multipass = true;
  f.depth_bits = 0;
  f.table_bits = f.newton = 0;
  return f;
}
using Frame = baked_frame::BakedFrame<std::uint32_t, true>;

// A forced filter: a RAM copy of the texture descriptors (the texels stay in flash).
std::array<TextureData, baked::texture_count ? baked::texture_count : 1> forced_textures;
PreparedScene forced_scene;

const PreparedScene& scene_for(const bench::Request& request) {
  if (!request.force_filter) return baked::scene;
  for (int t = 0; t < baked::texture_count; ++t) {
    forced_textures[static_cast<std::size_t>(t)] = baked::scene.textures[t];
    forced_textures[static_cast<std::size_t>(t)].filter = request.filter;
  }
  forced_scene = baked::scene;
  forced_scene.textures = forced_textures.data();
  return forced_scene;
}

const char* pass_name(Pass p) {
  switch (p) {
    case Pass::shadow_depth: return "shadow";
    case Pass::depth_ambient: return "depth_ambient";
    case Pass::light: return "light";
    case Pass::modulate: return "modulate";
    case Pass::fused: return "fused";
  }
  return "?";
}

// With --per-pass, each pass is a measured region and its name is logged in order.
struct PassRegions : NoHooks {
  hal::CostCounter* cost;
  hal::LogLine<400>* names;
  void pass_begin(Pass p, int projector) {
    *names << " " << pass_name(p);
    if (projector >= 0) *names << projector;
    cost->begin();
  }
  void pass_end(Pass, int) { cost->end(); }
};

// FNV-1a over the colour buffer's bytes as stored, the same bytes as the host's FixedFrame::raw.
std::uint32_t frame_hash() {
  std::uint32_t h = 2166136261u;
  for (const baked_frame::Color::Storage value : Frame::color) {
    for (std::size_t b = 0; b < sizeof value; ++b) {
      h ^= static_cast<std::uint8_t>(static_cast<std::uint32_t>(value) >> (8 * b));
      h *= 16777619u;
    }
  }
  return h;
}

RenderStatus render_measured(const PreparedScene& scene, const bench::Request& request) {
  const Frame::Target target = Frame::target();
  return dispatch<bench_features(), false, true>(request.knobs, [&]<Features F>() {
    hal::CostCounter cost;
    if (!request.per_pass) {
      cost.begin();
      const RenderStatus status = render_frame<F>(scene, baked::matrices, target, request.knobs);
      cost.end();
      return status;
    }
    hal::LogLine<400> names;
    names << "sweep_bench: regions";
    const RenderStatus status = render_frame<F>(scene, baked::matrices, target, request.knobs, PassRegions{{}, &cost, &names});
    hal::log_line(names);
    return status;
  });
}

}  // namespace

int spanlight::hal::app_main(Args args) {
  bench::Request request;
  request.knobs = baked::knobs;  // a knob not on the command line is the baked one (the format among them)
  const char* bad = nullptr;
  if (!bench::parse_request(args, request, bad)) {
    log_line(LogLine() << "sweep_bench: bad argument " << (bad ? bad : "?"));
    return 2;
  }
  if (request.knobs.newton > 1) {  // dispatch compiles Newton 0 and 1 only
    log_line("sweep_bench: --newton 2 is not compiled into the bench");
    return 2;
  }
  const RenderStatus status = render_measured(scene_for(request), request);
  log_line(LogLine<320>() << "sweep_bench: scene=" << baked::scene_name
                          << " format=" << knob_value(request.knobs, "format") << " status=" << describe(status)
                          << " hash=" << Hex{frame_hash()} << ", covered " << Frame::covered_pixels(request.knobs.depth_bits)
                          << " pixels, stack peak " << stack_peak_bytes() << " bytes");
  return status == RenderStatus::ok ? 0 : 1;
}
