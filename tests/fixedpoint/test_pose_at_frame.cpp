// pose_at_frame (pose_at_frame.hpp): key frames interpolate to the exactly rounded
// linear interpolant, an orbit's angle is the exactly rounded fraction of a turn,
// and its eye is within the sine's bound of the circle.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "fixedpoint/look_at.hpp"
#include "fixedpoint/perspective.hpp"
#include "fixedpoint/pose_at_frame.hpp"

namespace {

using fixedpoint::KeyFrame;
using fixedpoint::Orbit;
using fixedpoint::Turns;
using fixedpoint::Vec3Q16;
using fixedpoint::ViewPose;
using i128 = __int128;

// n / d rounded to nearest, ties away from zero, exactly.
i128 reference_divide(i128 n, i128 d) {
  const i128 mag = n < 0 ? -n : n;
  const i128 q = (2 * mag + d) / (2 * d);
  return n < 0 ? -q : q;
}

std::int32_t reference_lerp(std::int64_t a, std::int64_t b, std::uint32_t step, std::uint32_t steps) {
  return static_cast<std::int32_t>(a + reference_divide(static_cast<i128>(b - a) * step, steps));
}

std::int32_t random_coordinate(std::mt19937_64& rng) {
  const std::int32_t limit = fixedpoint::pose_coordinate_limit;
  return static_cast<std::int32_t>(static_cast<std::int64_t>(rng() % (2 * static_cast<std::uint64_t>(limit) - 1)) - (limit - 1));
}

Vec3Q16 random_point(std::mt19937_64& rng) { return {random_coordinate(rng), random_coordinate(rng), random_coordinate(rng)}; }

ViewPose random_view(std::mt19937_64& rng) {
  const Turns fovy{fixedpoint::min_fovy_raw + static_cast<std::uint32_t>(rng() % (fixedpoint::max_fovy_raw - fixedpoint::min_fovy_raw + 1))};
  return {random_point(rng), random_point(rng), random_point(rng), fovy};
}

void require_same(const Vec3Q16& a, const Vec3Q16& b) {
  REQUIRE(a.x == b.x);
  REQUIRE(a.y == b.y);
  REQUIRE(a.z == b.z);
}

void require_same(const ViewPose& a, const ViewPose& b) {
  require_same(a.eye, b.eye);
  require_same(a.target, b.target);
  require_same(a.up, b.up);
  REQUIRE(a.fovy == b.fovy);
}

}  // namespace

TEST_CASE("key frames interpolate to the exactly rounded linear interpolant and hold at the ends", "[pose_at_frame]") {
  std::mt19937_64 rng(20240630);
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<KeyFrame> keys;
    std::uint32_t frame = static_cast<std::uint32_t>(rng() % 50);
    const int count = 1 + static_cast<int>(rng() % 5);
    for (int k = 0; k < count; ++k) {
      keys.push_back({frame, random_view(rng)});
      frame += 1 + static_cast<std::uint32_t>(rng() % 300);
    }
    const std::uint32_t last = keys.back().frame;
    for (std::uint32_t f = 0; f <= last + 5; ++f) {
      const ViewPose got = fixedpoint::pose_at_frame(keys.data(), static_cast<std::uint32_t>(keys.size()), f);
      INFO("trial " << trial << ", frame " << f);
      if (f <= keys.front().frame) {
        require_same(got, keys.front().pose);
        continue;
      }
      if (f >= last) {
        require_same(got, keys.back().pose);
        continue;
      }
      std::size_t i = 1;
      while (keys[i].frame < f) ++i;
      const ViewPose& a = keys[i - 1].pose;
      const ViewPose& b = keys[i].pose;
      const std::uint32_t step = f - keys[i - 1].frame, steps = keys[i].frame - keys[i - 1].frame;
      const auto lerp = [&](const Vec3Q16& p, const Vec3Q16& q) {
        return Vec3Q16{reference_lerp(p.x, q.x, step, steps), reference_lerp(p.y, q.y, step, steps), reference_lerp(p.z, q.z, step, steps)};
      };
      const ViewPose expected{lerp(a.eye, b.eye), lerp(a.target, b.target), lerp(a.up, b.up),
                              Turns{static_cast<std::uint32_t>(reference_lerp(a.fovy.raw, b.fovy.raw, step, steps))}};
      require_same(got, expected);
    }
  }
}

TEST_CASE("an orbit's angle is turns * frame / frame_count of a turn, exactly rounded, and closes after whole turns", "[pose_at_frame]") {
  std::mt19937_64 rng(20240631);
  for (int trial = 0; trial < 100000; ++trial) {
    const auto count = static_cast<std::uint32_t>(1 + rng() % (fixedpoint::max_frame_count - 1));
    const auto frame = static_cast<std::uint32_t>(rng() % count);
    const auto turns = static_cast<std::int32_t>(static_cast<std::int64_t>(rng() % 32767) - 16383);
    const i128 exact = reference_divide(static_cast<i128>(turns) * frame * (i128{1} << 32), count);
    const auto expected = static_cast<std::uint32_t>(static_cast<std::uint64_t>(exact & 0xFFFFFFFF));
    INFO("turns " << turns << ", frame " << frame << " of " << count);
    REQUIRE(fixedpoint::detail::orbit_angle(turns, frame, count) == expected);
    REQUIRE(fixedpoint::detail::orbit_angle(turns, count, count) == 0u);
  }
}

TEST_CASE("an orbit's eye lies on its circle within the sine's error", "[pose_at_frame]") {
  std::mt19937_64 rng(20240632);
  for (int trial = 0; trial < 100000; ++trial) {
    Orbit orbit{};
    orbit.center = {static_cast<std::int32_t>(rng() % (1u << 28)), random_coordinate(rng), -static_cast<std::int32_t>(rng() % (1u << 28))};
    orbit.radius = fixedpoint::q16::from_raw(static_cast<std::int32_t>(rng() % (1u << 29)));
    orbit.start = Turns{static_cast<std::uint32_t>(rng())};
    orbit.turns = static_cast<std::int32_t>(rng() % 7) - 3;
    orbit.target = random_point(rng);
    orbit.up = random_point(rng);
    orbit.fovy = fixedpoint::turns_from_degrees(40);
    const auto count = static_cast<std::uint32_t>(1 + rng() % 1000);
    const auto frame = static_cast<std::uint32_t>(rng() % count);
    const ViewPose pose = fixedpoint::pose_at_frame(orbit, frame, count);
    const Turns angle{orbit.start.raw + fixedpoint::detail::orbit_angle(orbit.turns, frame, count)};
    const long double a = static_cast<long double>(angle.raw) * 2 * 3.141592653589793238462643383279502884L / 4294967296.0L;
    // Raw Q15.16 units: the radius times the sine's error, and the final rounding.
    const long double bound = orbit.radius.raw() * fixedpoint::sin_cos_error * std::ldexp(1.0L, -30) + 0.5L;
    INFO("trial " << trial);
    REQUIRE(std::fabs(pose.eye.x - (orbit.center.x + orbit.radius.raw() * std::sin(a))) <= bound);
    REQUIRE(pose.eye.y == orbit.center.y);
    REQUIRE(std::fabs(pose.eye.z - (orbit.center.z + orbit.radius.raw() * std::cos(a))) <= bound);
    require_same(pose.target, orbit.target);
    require_same(pose.up, orbit.up);
    REQUIRE(pose.fovy == orbit.fovy);
  }
}

TEST_CASE("an orbit that leaves the coordinate range gives a pose look_at refuses", "[pose_at_frame]") {
  Orbit orbit{};
  orbit.center = {(1 << 30) - (1 << 16), 0, 0};
  orbit.radius = fixedpoint::q16::max();  // almost 2^15: the eye saturates beyond 2^14
  orbit.turns = 1;
  orbit.target = {0, 0, 0};
  orbit.up = {0, 1 << 16, 0};
  orbit.start = Turns{1u << 30};  // eye towards +x
  const ViewPose pose = fixedpoint::pose_at_frame(orbit, 0, 60);
  REQUIRE(pose.eye.x == INT32_MAX);
  REQUIRE(fixedpoint::look_at(pose.eye, pose.target, pose.up).status == fixedpoint::PoseStatus::coordinate_out_of_range);
}

TEST_CASE("a track plays its key frames, or its orbit when it has none", "[pose_at_frame]") {
  const KeyFrame keys[2] = {{0, {{0, 0, 0}, {0, 0, -65536}, {0, 65536, 0}, Turns{1u << 28}}},
                            {10, {{655360, 0, 0}, {0, 0, -65536}, {0, 65536, 0}, Turns{1u << 28}}}};
  Orbit orbit{};
  orbit.radius = fixedpoint::q16::from_int(2);
  orbit.turns = 1;
  const fixedpoint::PoseTrack with_keys{keys, 2, orbit}, orbiting{nullptr, 0, orbit};
  REQUIRE(fixedpoint::pose_at_frame(with_keys, 5, 60).eye.x == 327680);
  require_same(fixedpoint::pose_at_frame(orbiting, 15, 60).eye, fixedpoint::pose_at_frame(orbit, 15, 60).eye);
  REQUIRE(fixedpoint::pose_at_frame(orbiting, 15, 60).eye.x == 2 * 65536);  // a quarter turn: +x
  REQUIRE(fixedpoint::pose_at_frame(nullptr, 0, 3).eye.x == 0);            // no keys: a zero pose
}
