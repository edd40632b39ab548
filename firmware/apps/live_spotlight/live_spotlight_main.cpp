// live_spotlight: the live-scene demo (docs/live-scenes.md). A shadowed spotlight
// orbits a room with a textured crate and a ball while the camera moves, for 60 frames
// (scenes/live_spotlight.json and its animation, baked with --animation). Each frame's
// pose is built here on the target (scene_pose_at_frame), its matrices too
// (render_frame_at_pose), and the frame is drawn in 15 bands of 16 rows into one band
// of colour and depth, each band pushed through the HAL's FrameSink as it is done.
// RAM is what the arrays below and the stack reserve hold (CMakeLists.txt): <= 64 KiB.
//   live_spotlight [OUT_PREFIX [STEP]]
// renders frames 0, STEP, 2 STEP, ... (STEP 1 by default) into OUT_PREFIX_NNNN.ppm ("-":
// render without writing). Measured regions: per frame the pose, its matrices and the
// rendering, paused while a band is pushed, so 16 regions a frame.
#include <array>
#include <cstdint>
#include <span>

#include "app_args.hpp"
#include "baked_config.hpp"
#include "band_sink.hpp"
#include "hal/hal.hpp"
#include "hal/log_line.hpp"
#include "spanlight/pose.hpp"
#include "spanlight/scene_animation.hpp"

namespace {

using namespace spanlight;
using Color = ColorTraits<baked::features.format>;

// The demo's own buffers rather than baked_frame's whole-frame ones: band-sized, and the 64 KiB
// working set docs/live-scenes.md states is counted from exactly these declarations.
constexpr std::uint16_t band_rows = 16;
constexpr std::uint32_t band_pixels = std::uint32_t{baked::width} * band_rows;
static_assert(baked::projector_count == 1 && baked::shadow_map_texels == 128 * 128, "the demo's RAM budget is for one 128^2 map");

std::array<Color::Storage, band_pixels * Color::per_pixel> color;
std::array<baked::Depth, band_pixels> depth;
std::array<baked::Depth, baked::shadow_map_texels> shadow_map;
std::array<std::uint8_t, baked::features.multipass ? tie_mask_bytes(band_pixels) : 1> tie_mask;
std::array<CachedVertex, baked::max_vertex_count> vertices;
std::array<std::uint8_t, std::size_t{baked::width} * 3> line;
std::array<Mat4Block, baked::object_count> clip_from_object;
std::array<Mat4Block, baked::object_count * baked::projector_count> projector_from_object, light_clip_from_object;
std::array<CameraPose, baked::projector_count> projector_poses;

// OUT_PREFIX_NNNN.ppm into `path` (prefix at most 40 characters).
bool frame_path(const char* prefix, std::uint32_t frame, std::span<char> path) {
  std::size_t n = 0;
  for (const char* c = prefix; *c != 0; ++c) {
    if (n + 10 >= path.size()) return false;
    path[n++] = *c;
  }
  path[n++] = '_';
  for (std::uint32_t digit = 1000; digit > 0; digit /= 10) path[n++] = static_cast<char>('0' + frame / digit % 10);
  for (const char c : {'.', 'p', 'p', 'm', '\0'}) path[n++] = c;
  return true;
}

}  // namespace

int spanlight::hal::app_main(Args args) {
  const char* prefix = args.size() > 1 ? args[1] : "frame";
  const bool write = !(prefix[0] == '-' && prefix[1] == 0);
  std::uint32_t step = 1;
  if (args.size() > 2 && !apps::parse_count(args[2], 1, baked::frame_count, step)) {
    log_line(LogLine() << "live_spotlight: step: expected an integer in 1.." << baked::frame_count << ", got " << args[2]);
    return 2;
  }
  const std::span<baked::Depth> maps[1] = {shadow_map};
  const FrameTarget<baked::features.format, baked::Depth> target{color, depth, maps, tie_mask, vertices, band_rows};
  const MatrixStorage storage{clip_from_object, projector_from_object, light_clip_from_object};
  CostCounter cost;
  for (std::uint32_t frame = 0; frame < baked::frame_count; frame += step) {
    hal::FrameSink sink;
    std::array<char, 48> path{};
    if (write && (!frame_path(prefix, frame, path) || !sink.open(path.data(), {baked::width, baked::height}))) {
      log_line(LogLine() << "live_spotlight: cannot write frame " << frame);
      return 1;
    }
    apps::BandSink<baked::features.format> bands{{}, write ? &sink : nullptr, line, baked::width, &cost};
    PoseResult pose_result;
    cost.begin();
    const FramePose pose = scene_pose_at_frame(baked::animation, frame, projector_poses);
    const RenderStatus status = render_frame_at_pose<baked::features>(baked::scene, pose, storage, target, baked::knobs, pose_result, bands);
    cost.end();
    if (status != RenderStatus::ok) {
      LogLine<> message;
      message << "live_spotlight: frame " << frame << ": " << describe(status);
      if (status == RenderStatus::bad_pose) {
        message << ": " << describe(pose_result.failure) << " " << pose_result.projector << ", object " << pose_result.object
                << ": " << fixedpoint::pose_status_name(pose_result.status);
      }
      log_line(message.c_str());
      return 1;
    }
    if (!bands.ok || (write && !sink.close())) {
      log_line(LogLine() << "live_spotlight: cannot write frame " << frame);
      return 1;
    }
    log_line(LogLine() << "live_spotlight: frame " << frame << " in " << (baked::height + band_rows - 1) / band_rows
                       << " bands");
  }
  log_line(LogLine() << "live_spotlight: " << baked::scene_name << " " << baked::width << "x" << baked::height << ", "
                     << baked::frame_count << " frames, step " << step << ", " << cost.elapsed() << " "
                     << CostCounter::unit() << ", stack peak " << stack_peak_bytes() << " bytes");
  return 0;
}
