// sweep_bench: the cost side of `spanlight sweep` on target. One ELF per baked
// scene holds the scene's eight reciprocal instantiations (table bits 6, 8, 10,
// 12 x Newton 0, 1); span, tolerance, depth bits, fused and the texture filter
// are runtime knobs. A run renders one frame with the configuration on its
// command line inside the measured region, logs the frame hash, and exits.
//   sweep_bench_<scene>.elf --table-bits 8 --newton 1 --span 16 --tolerance 3
//                           --depth-bits 24 --fused 0 --filter scene [--passes]
#include "bench_features.hpp"
#include "hal/log_line.hpp"
#include "render_config.hpp"
#include "scene_filter.hpp"

int spanlight::hal::app_main(Args args) {
  bench::Request request;
  const char* bad = nullptr;
  if (!bench::parse_request(args, request, bad)) {
    log_line(LogLine() << "sweep_bench: bad argument " << (bad ? bad : "?"));
    return 2;
  }
  const PreparedScene* scene = bench::scene_with_filter(baked::scene, request.filter);
  if (scene == nullptr) {
    log_line("sweep_bench: too many textures to force a filter");
    return 2;
  }
  RenderStatus status = RenderStatus::ok;
  // Newton is 0 or 1 (parse_request): pick the instance by table size, then steps.
  const bool one = request.newton == 1;
  switch (request.table_bits) {
    case 6: status = one ? bench::render_instance_6_1(*scene, request) : bench::render_instance_6_0(*scene, request); break;
    case 8: status = one ? bench::render_instance_8_1(*scene, request) : bench::render_instance_8_0(*scene, request); break;
    case 10: status = one ? bench::render_instance_10_1(*scene, request) : bench::render_instance_10_0(*scene, request); break;
    default: status = one ? bench::render_instance_12_1(*scene, request) : bench::render_instance_12_0(*scene, request); break;
  }
  const Precision& p = request.precision;
  log_line(LogLine<240>() << "sweep_bench: scene=" << baked::scene_name << " format="
                          << (baked::Features::format == PixelFormat::rgb565 ? "rgb565" : "rgb888")
                          << " table_bits=" << request.table_bits << " newton=" << request.newton
                          << " span_log2=" << p.span_log2 << " tolerance=" << p.span_tolerance_log2
                          << " depth_bits=" << p.depth_bits << " fused=" << (p.fused ? 1 : 0)
                          << " filter=" << bench::to_string(request.filter) << " status=" << static_cast<int>(status)
                          << " hash=" << Hex{bench::frame_hash()} << " stack=" << stack_peak_bytes());
  return status == RenderStatus::ok ? 0 : 1;
}
