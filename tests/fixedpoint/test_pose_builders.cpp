// The run-time pose builders against GLM (double) over seeded random poses, each
// entry within the bound derived from the formats and approximations (the
// derivation: pose_reference.hpp, and the headers it names), and the block
// arithmetic (quantisation, product) against exact integer references.
#include <catch2/catch.hpp>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <random>

#include "fixedpoint/mat4.hpp"
#include "pose_reference.hpp"
#include "random_poses.hpp"

namespace {

using fixedpoint::Mat4;
using fixedpoint::Mat4Block;
using fixedpoint::PoseStatus;
using i128 = __int128;

#if defined(__SANITIZE_ADDRESS__)
constexpr int poses_per_regime = 1 << 9;
#else
constexpr int poses_per_regime = 1 << 12;
#endif

// The largest |value| + bound of an expected matrix: how far its entries might reach.
double reach(const pose_reference::Expected& expected) {
  double r = 0.0;
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) r = std::fmax(r, std::fabs(expected.value[c][row]) + expected.bound[c][row]);
  return r;
}

// A builder that refused with entry_out_of_range must have had an entry at or beyond 2^29
// (within that entry's bound): the status is never a spurious one.
void require_matches(const Mat4& built, const pose_reference::Expected& expected, const char* what) {
  INFO(what);
  if (built.status == PoseStatus::entry_out_of_range) {
    REQUIRE(reach(expected) >= std::ldexp(1.0, 29) - 0.5);
    return;
  }
  REQUIRE(built.status == PoseStatus::ok);
  const pose_reference::Comparison c = pose_reference::compare(built, expected);
  INFO("worst error / bound " << c.worst_bound_ratio);
  REQUIRE(c.worst_bound_ratio <= 1.0);
}

// Likewise the pipeline's block: beyond_pipeline_range only when an entry reaches 2^13
// (frac_bits 16 would round it to 2^29), entry_out_of_range only beyond 2^29.
void require_matches(const fixedpoint::BlockResult& built, const pose_reference::Expected& expected, const char* what) {
  INFO(what);
  if (built.status == PoseStatus::beyond_pipeline_range) {
    REQUIRE(reach(expected) >= std::ldexp(1.0, 13) - std::ldexp(1.0, -17));
    return;
  }
  if (built.status == PoseStatus::entry_out_of_range) {
    REQUIRE(reach(expected) >= std::ldexp(1.0, 29) - 0.5);
    return;
  }
  REQUIRE(built.status == PoseStatus::ok);
  const pose_reference::Comparison c = pose_reference::compare(built.block, expected);
  INFO("frac_bits " << built.block.frac_bits << ", worst error / bound " << c.worst_bound_ratio);
  REQUIRE(c.worst_bound_ratio <= 1.0);
}

// round(|x| * 2^shift), ties away from zero, exactly.
i128 reference_round(i128 x, int shift) {
  const i128 mag = x < 0 ? -x : x;
  i128 r = 0;
  if (shift >= 0) {
    r = mag << shift;
  } else if (shift > -126) {
    r = (mag + (static_cast<i128>(1) << (-shift - 1))) >> -shift;
  }
  return x < 0 ? -r : r;
}

// Entries of every size (not just near 2^29) and a random exponent per column.
Mat4 random_mat4(std::mt19937_64& rng) {
  Mat4 a{};
  for (int col = 0; col < 4; ++col) {
    const int bits = 1 + static_cast<int>(rng() % 29);
    for (int row = 0; row < 4; ++row) {
      const auto m = static_cast<std::int32_t>(static_cast<std::int64_t>(rng() % (std::uint64_t{1} << bits)) - (std::int64_t{1} << (bits - 1)));
      a.m[col * 4 + row] = rng() % 5 == 0 ? 0 : std::max(m, -fixedpoint::mat4_block_entry_limit + 1);  // some zeros, as in P and B
    }
    a.frac_bits[col] = static_cast<int>(rng() % 61);
  }
  a.status = PoseStatus::ok;
  return a;
}

// The canonical quantisation of exact values at frac `frac`: the largest frac_bits <= 60 with
// every rounded |entry| < 2^29 (rounding is monotone, so the largest entry decides), or -1.
int reference_frac_bits(const i128* exact, int count, int frac) {
  i128 largest = 0;
  for (int i = 0; i < count; ++i) largest = std::max(largest, exact[i] < 0 ? -exact[i] : exact[i]);
  int f = 60;
  while (f >= 0 && reference_round(largest, f - frac) >= (i128{1} << 29)) --f;
  return f;
}

}  // namespace

TEST_CASE("look_at, perspective and the chains P (V M) and B P (V M) match GLM within the derived bound", "[poses]") {
  for (const random_poses::Regime& regime : random_poses::regimes) {
    std::mt19937_64 rng(regime.seed);
    for (int i = 0; i < poses_per_regime; ++i) {
      const random_poses::Pose p = random_poses::pose(rng, regime);
      const random_poses::Built b = random_poses::build(p);
      INFO(regime.name << " pose " << i << ", fovy raw " << p.fovy.raw);
      require_matches(b.view, b.view_expected, "mat4(look_at)");
      require_matches(b.projection, b.projection_expected, "perspective");
      require_matches(b.view_from_object, b.view_from_object_expected, "V * M");
      REQUIRE(b.projection.status == PoseStatus::ok);
      REQUIRE(b.view_from_object.status == PoseStatus::ok);
      require_matches(b.clip_from_object, b.clip_expected, "P * (V * M)");
      if (b.clip_from_object.status == PoseStatus::ok) {
        require_matches(b.texture_from_object, b.texture_expected, "B * (P * (V * M))");
        require_matches(b.clip_block, b.clip_block_expected, "pipeline_matrix(P * (V * M))");
      } else {
        REQUIRE(b.texture_from_object.status == b.clip_from_object.status);  // the chain's first failure
        REQUIRE(b.clip_block.status == b.clip_from_object.status);
      }
      if (b.texture_from_object.status == PoseStatus::ok) {
        require_matches(b.texture_block, b.texture_block_expected, "pipeline_matrix(B * (P * (V * M)))");
      }
      require_matches(b.clip_left_to_right, b.clip_left_to_right_expected, "(P * mat4(V)) * M");
    }
  }
}

TEST_CASE("a product column is its terms aligned to the coarsest, summed exactly and rounded once", "[poses]") {
  std::mt19937_64 rng(20240616);
  for (int i = 0; i < 20000; ++i) {
    const Mat4 a = random_mat4(rng), b = random_mat4(rng);
    const Mat4 product = a * b;
    INFO("case " << i);
    bool beyond = false;
    Mat4 expected{};
    for (int col = 0; col < 4; ++col) {
      int coarsest = 60;
      for (int k = 0; k < 4; ++k)
        if (b.m[col * 4 + k] != 0) coarsest = std::min(coarsest, a.frac_bits[k]);
      i128 exact[4];
      for (int row = 0; row < 4; ++row) {
        exact[row] = 0;
        for (int k = 0; k < 4; ++k) {
          const i128 term = static_cast<i128>(a.m[k * 4 + row]) * b.m[col * 4 + k];
          exact[row] += reference_round(term, coarsest - a.frac_bits[k]);
        }
      }
      const int frac = coarsest + b.frac_bits[col];
      expected.frac_bits[col] = reference_frac_bits(exact, 4, frac);
      if (expected.frac_bits[col] < 0) beyond = true;
      for (int row = 0; row < 4; ++row) {
        expected.m[col * 4 + row] = static_cast<std::int32_t>(reference_round(exact[row], expected.frac_bits[col] - frac));
      }
    }
    if (beyond) {
      REQUIRE(product.status == PoseStatus::entry_out_of_range);
      continue;
    }
    REQUIRE(product.status == PoseStatus::ok);
    for (int col = 0; col < 4; ++col) REQUIRE(product.frac_bits[col] == expected.frac_bits[col]);
    for (int e = 0; e < 16; ++e) REQUIRE(product.m[e] == expected.m[e]);
  }
}

TEST_CASE("a product is within 1.5 units of its coarsest term's place plus its rounding of the exact product", "[poses]") {
  std::mt19937_64 rng(20240618);
  for (int i = 0; i < 20000; ++i) {
    const Mat4 a = random_mat4(rng), b = random_mat4(rng);
    const Mat4 product = a * b;
    if (product.status != PoseStatus::ok) continue;
    const glm::dmat4 exact = pose_reference::to_glm(a) * pose_reference::to_glm(b);
    const glm::dmat4 got = pose_reference::to_glm(product);
    const glm::dmat4 magnitude = pose_reference::abs(pose_reference::to_glm(a)) * pose_reference::abs(pose_reference::to_glm(b));
    int coarsest = 60;
    for (const int f : a.frac_bits) coarsest = std::min(coarsest, f);
    for (int col = 0; col < 4; ++col) {
      for (int row = 0; row < 4; ++row) {
        // The bound of mat4.hpp; double's own error on the reference is below 2^-50 of the magnitudes.
        const double bound = 1.5 * std::ldexp(1.0, -(coarsest + b.frac_bits[col])) + std::ldexp(1.0, -(product.frac_bits[col] + 1)) +
                             std::ldexp(magnitude[col][row], -50);
        INFO("case " << i << ", column " << col << ", row " << row);
        REQUIRE(std::fabs(got[col][row] - exact[col][row]) <= bound);
      }
    }
  }
}

TEST_CASE("block_from_scaled and each column of mat4_from_scaled round as mat4_block_from_doubles does", "[poses]") {
  std::mt19937_64 rng(20240617);
  for (int i = 0; i < 20000; ++i) {
    // Mantissas below 2^52 and a power-of-two scale: the doubles are exact, so both must agree to the bit.
    fixedpoint::Scaled entries[16];
    double values[16];
    const int frac = static_cast<int>(rng() % 100) - 20;
    const int bits = 1 + static_cast<int>(rng() % 52);
    for (int e = 0; e < 16; ++e) {
      const auto mantissa = static_cast<std::int64_t>(rng() % (std::uint64_t{1} << bits)) - (std::int64_t{1} << (bits - 1));
      entries[e] = {mantissa, frac};
      values[e] = std::ldexp(static_cast<double>(mantissa), -frac);
    }
    const fixedpoint::BlockResult built = fixedpoint::block_from_scaled(entries);
    const Mat4Block from_doubles = fixedpoint::mat4_block_from_doubles(values);
    double largest = 0.0;
    for (const double v : values) largest = std::fmax(largest, std::fabs(v));
    INFO("case " << i << ", frac " << frac << ", largest " << largest);
    if (largest >= std::ldexp(1.0, 29) - 0.5) {  // beyond the format even at frac_bits 0
      REQUIRE(built.status == PoseStatus::entry_out_of_range);
    } else {
      REQUIRE(built.status == PoseStatus::ok);
      REQUIRE(built.block.frac_bits == from_doubles.frac_bits);
      for (int e = 0; e < 16; ++e) REQUIRE(built.block.m[e] == from_doubles.m[e]);
    }
    const Mat4 columns = fixedpoint::mat4_from_scaled(entries);
    for (int col = 0; col < 4; ++col) {
      double column[16] = {};
      for (int row = 0; row < 4; ++row) column[row] = values[col * 4 + row];
      const Mat4Block alone = fixedpoint::mat4_block_from_doubles(column);
      double column_largest = 0.0;
      for (const double v : column) column_largest = std::fmax(column_largest, std::fabs(v));
      if (column_largest >= std::ldexp(1.0, 29) - 0.5) {
        REQUIRE(columns.status == PoseStatus::entry_out_of_range);
        break;
      }
      if (columns.status != PoseStatus::ok) continue;  // another column is beyond the format
      REQUIRE(columns.frac_bits[col] == alone.frac_bits);
      for (int row = 0; row < 4; ++row) REQUIRE(columns.m[col * 4 + row] == alone.m[row]);
    }
  }
}

TEST_CASE("bias is B = translate(1/2) * scale(1/2), exactly", "[poses]") {
  const Mat4 b = fixedpoint::bias();
  REQUIRE(b.status == PoseStatus::ok);
  REQUIRE(pose_reference::to_glm(b) == pose_reference::expected_bias().value);
}

TEST_CASE("the first failure of a chain is the chain's status", "[poses]") {
  const Mat4 good = fixedpoint::bias();
  const fixedpoint::View bad_view = fixedpoint::look_at({0, 0, 0}, {0, 0, 0}, {0, 1 << 16, 0});
  const Mat4 bad_projection = fixedpoint::perspective(fixedpoint::Turns{0}, {1, 1}, fixedpoint::q16::from_int(1),
                                                      fixedpoint::q16::from_int(2));
  REQUIRE((good * fixedpoint::mat4(bad_view)).status == PoseStatus::eye_equals_target);
  REQUIRE((bad_view * good).status == PoseStatus::eye_equals_target);
  REQUIRE((bad_projection * (bad_view * good)).status == PoseStatus::fovy_out_of_range);
  REQUIRE((good * (bad_view * bad_projection)).status == PoseStatus::eye_equals_target);
  const fixedpoint::View good_view = fixedpoint::look_at({0, 0, 0}, {0, 0, -(1 << 16)}, {0, 1 << 16, 0});
  REQUIRE((good_view * bad_projection).status == PoseStatus::fovy_out_of_range);
}
