// The pose of a camera or projector as a function of the frame number, in
// integers, so the firmware and the host compute the same bits for every frame
// (host_tools/scene/animation.hpp reads it from an animation file,
// docs/animation-format.md). Two kinds of motion:
//   key frames, linearly interpolated: each coordinate is
//       a + round((b - a) * (frame - frame_a) / (frame_b - frame_a)),
//     exactly rounded to nearest (ties away from zero), fovy likewise in Turns;
//     before the first key the first pose holds, after the last the last one;
//   an orbit: eye = center + radius * (sin a, 0, cos a) with
//       a = start + round(turns * frame / frame_count) (in Turns, exactly rounded),
//     target, up and fovy fixed: a = 0 puts the eye on +z of the centre, 1/4 turn on +x.
// Frame numbers and frame counts are below 2^16. Key coordinates (raw Q15.16) must be
// within the builders' |raw| < 2^30 (then every interpolated one is too); an orbit that
// leaves that range gives a pose look_at refuses (coordinate_out_of_range).
#pragma once

#include <cstdint>

#include "fixedpoint/bits.hpp"
#include "fixedpoint/divide.hpp"
#include "fixedpoint/q.hpp"
#include "fixedpoint/trig.hpp"
#include "fixedpoint/vec.hpp"

namespace fixedpoint {

struct ViewPose {
  Vec3Q16 eye, target, up;
  Turns fovy;
};

struct KeyFrame {
  std::uint32_t frame;
  ViewPose pose;
};

struct Orbit {
  Vec3Q16 center;
  q16 radius;
  Turns start;         // the angle at frame 0
  std::int32_t turns;  // whole turns over frame_count frames; negative turns the other way
  Vec3Q16 target, up;
  Turns fovy;
};

// One animated view: key frames (sorted by frame, strictly increasing), or, when
// keys is null, the orbit.
struct PoseTrack {
  const KeyFrame* keys;
  std::uint32_t key_count;
  Orbit orbit;
};

inline constexpr std::uint32_t max_frame_count = 1u << 16;  // frames 0 .. 65535

namespace detail {

// a + (b - a) * step / steps, rounded; 0 < step < steps < 2^16, |b - a| < 2^31.
constexpr std::int64_t interpolate(std::int64_t a, std::int64_t b, std::uint32_t step, std::uint32_t steps) {
  const std::int64_t delta_times_step = mul_s32(static_cast<std::int32_t>(b - a), static_cast<std::int32_t>(step));
  return a + divide_rounded(delta_times_step, steps);  // |quotient| < |b - a| < 2^32
}

constexpr std::int32_t interpolate(std::int32_t a, std::int32_t b, std::uint32_t step, std::uint32_t steps) {
  return static_cast<std::int32_t>(interpolate(std::int64_t{a}, std::int64_t{b}, step, steps));
}

constexpr ViewPose interpolate(const ViewPose& a, const ViewPose& b, std::uint32_t step, std::uint32_t steps) {
  const auto point = [&](const Vec3Q16& p, const Vec3Q16& q) {
    return Vec3Q16{interpolate(p.x, q.x, step, steps), interpolate(p.y, q.y, step, steps), interpolate(p.z, q.z, step, steps)};
  };
  // fovy is below 1/2 turn (perspective's range), so the raw difference fits int32.
  const auto fovy = static_cast<std::uint32_t>(interpolate(std::int64_t{a.fovy.raw}, std::int64_t{b.fovy.raw}, step, steps));
  return {point(a.eye, b.eye), point(a.target, b.target), point(a.up, b.up), Turns{fovy}};
}

// turns * frame / frame_count of a turn, rounded, modulo one turn. |turns * frame| < 2^31.
constexpr std::uint32_t orbit_angle(std::int32_t turns, std::uint32_t frame, std::uint32_t frame_count) {
  const std::int64_t n = mul_s32(turns, static_cast<std::int32_t>(frame));
  const std::uint64_t magnitude = n < 0 ? static_cast<std::uint64_t>(-n) : static_cast<std::uint64_t>(n);
  // Whole turns vanish modulo 2^32: only the remainder of |n| / frame_count matters.
  const std::uint32_t remainder = div_mod(magnitude, frame_count).remainder;
  const auto fraction = static_cast<std::uint32_t>(divide_rounded(std::int64_t{remainder} << 32, frame_count));  // < 2^32
  return n < 0 ? 0u - fraction : fraction;
}

}  // namespace detail

constexpr ViewPose pose_at_frame(const KeyFrame* keys, std::uint32_t key_count, std::uint32_t frame) {
  if (key_count == 0) return ViewPose{};  // no view: look_at reports eye_equals_target
  if (frame <= keys[0].frame) return keys[0].pose;
  for (std::uint32_t i = 1; i < key_count; ++i) {
    const KeyFrame& a = keys[i - 1];
    const KeyFrame& b = keys[i];
    if (frame == b.frame) return b.pose;
    // a.frame < frame < b.frame, so the step count is positive.
    if (frame < b.frame) return detail::interpolate(a.pose, b.pose, frame - a.frame, b.frame - a.frame);
  }
  return keys[key_count - 1].pose;
}

constexpr ViewPose pose_at_frame(const Orbit& orbit, std::uint32_t frame, std::uint32_t frame_count) {
  const std::uint32_t count = frame_count == 0 ? 1 : frame_count;
  const SinCos a = sin_cos(Turns{orbit.start.raw + detail::orbit_angle(orbit.turns, frame, count)});
  // radius (Q15.16) times sin or cos (Q1.30) is Q.46, rounded to Q.16; saturated, so a
  // radius that carries the eye out of range yields a pose look_at refuses, never a wrapped one.
  const auto offset = [&](std::int32_t unit) { return shift_right_rounded(mul_s32(orbit.radius.raw(), unit), 30); };
  const Vec3Q16 eye{saturate32(orbit.center.x + offset(a.sin)), orbit.center.y, saturate32(orbit.center.z + offset(a.cos))};
  return {eye, orbit.target, orbit.up, orbit.fovy};
}

constexpr ViewPose pose_at_frame(const PoseTrack& track, std::uint32_t frame, std::uint32_t frame_count) {
  return track.keys != nullptr ? pose_at_frame(track.keys, track.key_count, frame)
                               : pose_at_frame(track.orbit, frame, frame_count);
}

}  // namespace fixedpoint
