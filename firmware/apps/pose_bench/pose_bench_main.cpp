// pose_bench: a camera on two key frames and a spotlight on an orbit around one
// object, for 60 frames, built with the run-time pose builders as the demo would:
//   clip_from_object = P_cam * (V_cam * M), light = P_j * (V_j * M),
//   light_clip_from_object = light, projector_from_object = B * light.
// Each frame logs its status and an FNV-1a hash of the three pipeline matrices; the
// host build logs the same lines, and the tests require them equal. Measured
// regions, in order: each frame's whole set of matrices (60), then, on frame 30,
// each builder alone (the order of `regions` below).
#include <cstdint>

#include "fixedpoint/look_at.hpp"
#include "fixedpoint/mat4.hpp"
#include "fixedpoint/perspective.hpp"
#include "fixedpoint/pose_at_frame.hpp"
#include "hal/hal.hpp"
#include "hal/log_line.hpp"

namespace {

using namespace fixedpoint;

constexpr std::uint32_t frame_count = 60;
constexpr std::int32_t one = 1 << 16;

// Evaluated by the compiler: no floating point reaches the target.
constexpr Turns camera_fovy = turns_from_degrees(55);
constexpr KeyFrame camera_keys[2] = {
    {0, {{0, 2 * one, 6 * one}, {0, one, 0}, {0, one, 0}, camera_fovy}},
    {59, {{3 * one, 3 * one, 4 * one}, {0, one / 2, 0}, {0, one, 0}, turns_from_degrees(45)}},
};
constexpr Orbit spotlight{{0, 3 * one, 0}, q16::from_int(2), Turns{0}, 1, {0, 0, 0}, {0, one, 0}, turns_from_degrees(40)};
constexpr double model_values[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0.5, 0.25, -0.75, 1};
constexpr Mat4Block model = mat4_block_from_doubles(model_values);
constexpr Aspect screen{320, 240};
const q16 camera_near = q16::from_raw(one / 10), camera_far = q16::from_int(40);
const q16 light_near = q16::from_raw(one / 2), light_far = q16::from_int(30);

struct FrameMatrices {
  BlockResult clip, light_clip, texture;
};

FrameMatrices frame_matrices(std::uint32_t frame) {
  const ViewPose c = pose_at_frame(camera_keys, 2, frame);
  const ViewPose p = pose_at_frame(spotlight, frame, frame_count);
  const Mat4 m = mat4(model);
  const Mat4 light = perspective(p.fovy, aspect_from_q16(q16::from_int(1)), light_near, light_far) * (look_at(p.eye, p.target, p.up) * m);
  return {pipeline_matrix(perspective(c.fovy, screen, camera_near, camera_far) * (look_at(c.eye, c.target, c.up) * m)),
          pipeline_matrix(light), pipeline_matrix(bias() * light)};
}

std::uint32_t fnv1a(std::uint32_t hash, std::uint32_t word) {
  for (int byte = 0; byte < 4; ++byte) {
    hash = (hash ^ ((word >> (8 * byte)) & 0xFFu)) * 16777619u;
  }
  return hash;
}

std::uint32_t hash_of(const BlockResult& r) {
  std::uint32_t h = fnv1a(2166136261u, static_cast<std::uint32_t>(r.status));
  h = fnv1a(h, static_cast<std::uint32_t>(r.block.frac_bits));
  for (const std::int32_t m : r.block.m) h = fnv1a(h, static_cast<std::uint32_t>(m));
  return h;
}

// Results land here, and the measured frame is read from memory, so the measured calls are
// neither optimised away nor evaluated by the compiler.
volatile std::uint32_t sink;
volatile std::uint32_t measured_frame = 30;

std::uint32_t word_of(const ViewPose& p) { return static_cast<std::uint32_t>(p.eye.x); }
template <typename Built>
std::uint32_t word_of(const Built& b) {
  return static_cast<std::uint32_t>(b.status);
}

template <typename Build>
void measure(spanlight::hal::CostCounter& cost, Build build) {
  cost.begin();
  const auto result = build();
  cost.end();
  sink = word_of(result);
}

}  // namespace

int spanlight::hal::app_main(Args /*args*/) {
  CostCounter frames;
  for (std::uint32_t frame = 0; frame < frame_count; ++frame) {
    frames.begin();
    const FrameMatrices f = frame_matrices(frame);
    frames.end();
    LogLine<> line;
    line << "frame " << frame << ": " << pose_status_name(f.clip.status) << " " << pose_status_name(f.light_clip.status)
         << " " << pose_status_name(f.texture.status) << " " << Hex{hash_of(f.clip)} << " " << Hex{hash_of(f.light_clip)}
         << " " << Hex{hash_of(f.texture)};
    log_line(line.c_str());
  }

  // Each builder alone, on frame 30's poses.
  const std::uint32_t frame = measured_frame;
  const ViewPose c = pose_at_frame(camera_keys, 2, frame);
  const View view = look_at(c.eye, c.target, c.up);
  const Mat4 projection = perspective(c.fovy, screen, camera_near, camera_far);
  const Mat4 view_model = view * mat4(model);
  const Mat4 clip = projection * view_model;
  CostCounter builders;
  measure(builders, [=] { return pose_at_frame(camera_keys, 2, frame); });
  measure(builders, [=] { return pose_at_frame(spotlight, frame, frame_count); });
  measure(builders, [&] { return look_at(c.eye, c.target, c.up); });
  measure(builders, [&] { return mat4(view); });
  measure(builders, [&] { return perspective(c.fovy, screen, camera_near, camera_far); });
  measure(builders, [&] { return view * mat4(model); });
  measure(builders, [&] { return projection * view_model; });
  measure(builders, [&] { return bias() * clip; });
  measure(builders, [&] { return pipeline_matrix(clip); });
  log_line("pose_bench: regions: 60 frames, then keys, orbit, look_at, mat4(view), perspective, view * model, "
           "P * VM, B * PVM, pipeline_matrix");
  return 0;
}
