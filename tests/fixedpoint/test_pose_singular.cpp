// The pose builders near their singular cases and at the ends of their ranges:
// a status where the matrix would be garbage or would not fit, and the GLM bound
// (pose_reference.hpp) just inside.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>

#include "fixedpoint/look_at.hpp"
#include "fixedpoint/mat4.hpp"
#include "fixedpoint/perspective.hpp"
#include "pose_reference.hpp"

namespace {

using fixedpoint::Aspect;
using fixedpoint::Mat4;
using fixedpoint::PoseStatus;
using fixedpoint::q16;
using fixedpoint::Turns;
using fixedpoint::Vec3Q16;

constexpr std::int32_t one = 1 << 16;  // 1.0 in Q15.16
constexpr std::int32_t limit = fixedpoint::pose_coordinate_limit;
const Turns fovy_60 = fixedpoint::turns_from_degrees(60);

void require_look_at_matches(const Vec3Q16& eye, const Vec3Q16& target, const Vec3Q16& up) {
  const Mat4 v = fixedpoint::mat4(fixedpoint::look_at(eye, target, up));
  REQUIRE(v.status == PoseStatus::ok);
  const auto c = pose_reference::compare(v, pose_reference::expected_look_at(eye, target, up, v));
  INFO("worst error / bound " << c.worst_bound_ratio);
  REQUIRE(c.worst_bound_ratio <= 1.0);
}

void require_perspective_matches(Turns fovy, Aspect aspect, q16 near, q16 far) {
  const Mat4 p = fixedpoint::perspective(fovy, aspect, near, far);
  REQUIRE(p.status == PoseStatus::ok);
  const auto c = pose_reference::compare(p, pose_reference::expected_perspective(fovy, aspect, near, far, p));
  INFO("worst error / bound " << c.worst_bound_ratio);
  REQUIRE(c.worst_bound_ratio <= 1.0);
}

PoseStatus perspective_status(std::uint32_t fovy_raw, Aspect aspect, std::int32_t near_raw, std::int32_t far_raw) {
  return fixedpoint::perspective(Turns{fovy_raw}, aspect, q16::from_raw(near_raw), q16::from_raw(far_raw)).status;
}

// up = (1, sine, 0) scaled, view along +x: the sine of their angle is sine / sqrt(1 + sine^2).
Vec3Q16 up_at_sine(double sine) { return {1 << 29, static_cast<std::int32_t>(std::lround(sine * (1 << 29))), 0}; }

}  // namespace

TEST_CASE("look_at refuses eye = target, a zero up and coordinates beyond 2^14", "[poses][singular]") {
  const Vec3Q16 up{0, one, 0};
  REQUIRE(fixedpoint::look_at({one, 2 * one, 3 * one}, {one, 2 * one, 3 * one}, up).status == PoseStatus::eye_equals_target);
  REQUIRE(fixedpoint::look_at({0, 0, 0}, {0, 0, -one}, {0, 0, 0}).status == PoseStatus::up_is_zero);
  for (const std::int32_t beyond : {limit, -limit, INT32_MAX, INT32_MIN}) {
    REQUIRE(fixedpoint::look_at({beyond, 0, 0}, {0, 0, -one}, up).status == PoseStatus::coordinate_out_of_range);
    REQUIRE(fixedpoint::look_at({0, 0, 0}, {0, beyond, -one}, up).status == PoseStatus::coordinate_out_of_range);
    REQUIRE(fixedpoint::look_at({0, 0, 0}, {0, 0, -one}, {0, 0, beyond}).status == PoseStatus::coordinate_out_of_range);
  }
  // Just inside: one LSB apart, and the largest coordinates (target - eye near 2^31 raw).
  require_look_at_matches({one, 2 * one, 3 * one}, {one + 1, 2 * one, 3 * one}, up);
  require_look_at_matches({limit - 1, -(limit - 1), limit - 1}, {-(limit - 1), limit - 1, -(limit - 1)}, {limit - 1, limit - 1, 0});
  require_look_at_matches({0, 0, 0}, {0, 0, -one}, {0, 1, 0});  // an up of one LSB
}

TEST_CASE("look_at refuses an up within sin 2^-20 of the view direction, and is accurate just outside", "[poses][singular]") {
  const Vec3Q16 eye{0, 0, 0}, target{100 * one, 0, 0};
  REQUIRE(fixedpoint::look_at(eye, target, {one, 0, 0}).status == PoseStatus::up_parallel_to_view);
  REQUIRE(fixedpoint::look_at(eye, target, {-3 * one, 0, 0}).status == PoseStatus::up_parallel_to_view);
  // The sine is computed within 2^-27, far inside these 3 % margins around 2^-20.
  REQUIRE(fixedpoint::look_at(eye, target, up_at_sine(std::ldexp(0.97, -20))).status == PoseStatus::up_parallel_to_view);
  REQUIRE(fixedpoint::look_at(eye, target, up_at_sine(std::ldexp(1.03, -20))).status == PoseStatus::ok);
  // The scene loader's own limit, 1e-6, is accepted; there the roll comes from an exact cross product.
  require_look_at_matches(eye, target, up_at_sine(1e-6));
  require_look_at_matches(eye, target, up_at_sine(std::ldexp(1.0, -19)));
  // Tilted: a view direction off the axes, up nearly along it.
  const Vec3Q16 d{3 * one, -4 * one, 12 * one};  // length 13
  REQUIRE(fixedpoint::look_at(eye, d, {6 * one, -8 * one, 24 * one}).status == PoseStatus::up_parallel_to_view);
  require_look_at_matches(eye, d, {6 * one, -8 * one + 8, 24 * one});  // sin ~ 8 / 2^16 / 26 * 12/13 ~ 4e-6
}

TEST_CASE("perspective refuses fovy near 0 and 180 degrees, and is accurate at the ends of its range", "[poses][singular]") {
  const Aspect square{1, 1};
  const std::int32_t near = one / 10, far = 100 * one;
  for (const std::uint32_t fovy : {0u, 1u, fixedpoint::min_fovy_raw - 1, fixedpoint::max_fovy_raw + 1, 1u << 31, UINT32_MAX}) {
    INFO("fovy raw " << fovy);
    REQUIRE(perspective_status(fovy, square, near, far) == PoseStatus::fovy_out_of_range);
  }
  for (const std::uint32_t fovy : {fixedpoint::min_fovy_raw, fixedpoint::min_fovy_raw + 1, (1u << 30) - 1, 1u << 30,
                                   (1u << 30) + 1, fixedpoint::max_fovy_raw - 1, fixedpoint::max_fovy_raw}) {
    INFO("fovy raw " << fovy);
    require_perspective_matches(Turns{fovy}, square, q16::from_raw(near), q16::from_raw(far));
  }
}

TEST_CASE("perspective refuses near <= 0, far <= near, a zero aspect and entries beyond the format", "[poses][singular]") {
  const Aspect square{1, 1};
  const std::uint32_t fovy = fovy_60.raw;
  REQUIRE(perspective_status(fovy, square, 0, one) == PoseStatus::near_not_positive);
  REQUIRE(perspective_status(fovy, square, -one, one) == PoseStatus::near_not_positive);
  REQUIRE(perspective_status(fovy, square, one, one) == PoseStatus::far_not_beyond_near);
  REQUIRE(perspective_status(fovy, square, 2 * one, one) == PoseStatus::far_not_beyond_near);
  REQUIRE(perspective_status(fovy, square, one, limit) == PoseStatus::coordinate_out_of_range);
  REQUIRE(perspective_status(fovy, {0, 1}, one, 2 * one) == PoseStatus::aspect_not_positive);
  REQUIRE(perspective_status(fovy, {1, 0}, one, 2 * one) == PoseStatus::aspect_not_positive);
  REQUIRE(fixedpoint::perspective(fovy_60, fixedpoint::aspect_from_q16(q16::from_raw(-one)), q16::from_int(1), q16::from_int(2)).status ==
          PoseStatus::aspect_not_positive);
  // far - near of one LSB at the far end: P22 = -(f + n) / (f - n) ~ -2^31, beyond 2^29.
  REQUIRE(perspective_status(fovy, square, limit - 2, limit - 1) == PoseStatus::entry_out_of_range);
  // A tall, narrow aspect of 1 / (2^32 - 1): P00 ~ 1.7 * 2^32.
  REQUIRE(perspective_status(fovy, {1, UINT32_MAX}, one, 2 * one) == PoseStatus::entry_out_of_range);
  // Inside: the smallest and largest depths, a wide aspect, one LSB of depth range.
  require_perspective_matches(fovy_60, square, q16::from_raw(1), q16::from_raw(limit - 1));
  require_perspective_matches(fovy_60, {4096, 1}, q16::from_raw(1), q16::from_raw(2));
  require_perspective_matches(fovy_60, {320, 240}, q16::from_int(1000), q16::from_raw(1000 * one + 512));
}

TEST_CASE("mat4 refuses a malformed block, and pipeline_matrix an entry the pipeline cannot take", "[poses][singular]") {
  fixedpoint::Mat4Block block{};
  block.frac_bits = 20;
  block.m[0] = fixedpoint::mat4_block_entry_limit - 1;
  REQUIRE(fixedpoint::mat4(block).status == PoseStatus::ok);
  block.m[0] = fixedpoint::mat4_block_entry_limit;
  REQUIRE(fixedpoint::mat4(block).status == PoseStatus::entry_out_of_range);
  block.m[0] = -fixedpoint::mat4_block_entry_limit;
  REQUIRE(fixedpoint::mat4(block).status == PoseStatus::entry_out_of_range);
  block.m[0] = 1;
  block.frac_bits = 61;
  REQUIRE(fixedpoint::mat4(block).status == PoseStatus::entry_out_of_range);
  block.frac_bits = -1;
  REQUIRE(fixedpoint::mat4(block).status == PoseStatus::entry_out_of_range);

  // The pipeline takes entries below 2^13: the block's own exponent is chosen from the values.
  block.frac_bits = 15;
  block.m[0] = (1 << 28) - 1;  // 2^13 - 2^-15
  const fixedpoint::BlockResult inside = fixedpoint::pipeline_matrix(fixedpoint::mat4(block));
  REQUIRE(inside.status == PoseStatus::ok);
  REQUIRE(inside.block.frac_bits == fixedpoint::mat4_block_pipeline_min_frac_bits);
  block.m[0] = 1 << 28;  // 2^13
  REQUIRE(fixedpoint::pipeline_matrix(fixedpoint::mat4(block)).status == PoseStatus::beyond_pipeline_range);
  const Mat4 failed{{}, {}, PoseStatus::up_is_zero};
  REQUIRE(fixedpoint::pipeline_matrix(failed).status == PoseStatus::up_is_zero);

  // A product beyond 2^29: 2^28 * 2^28 * 4 at frac_bits 0.
  fixedpoint::Mat4Block big{};
  for (std::int32_t& m : big.m) m = 1 << 28;
  big.frac_bits = 0;
  REQUIRE((fixedpoint::mat4(big) * fixedpoint::mat4(big)).status == PoseStatus::entry_out_of_range);
}
