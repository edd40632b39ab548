// spanlight_pose_accuracy: the measured error of the run-time pose builders
// against GLM over the random poses test_pose_builders.cpp checks (same seeds
// and counts), for docs/poses.md. Per matrix: the worst error relative to the
// largest GLM entry, in units of the last place (a Mat4's coarsest column; the
// pipeline's block), and against the derived bound (<= 1 is what the test requires).
#include <cstdio>
#include <random>
#include <type_traits>

#include "random_poses.hpp"

namespace {

struct Row {
  const char* name;
  pose_reference::Comparison worst;
  int refused = 0;  // entry_out_of_range: an entry at or beyond 2^29
};

template <typename Built>
void add(Row& row, const Built& built, const pose_reference::Expected& expected) {
  if (built.status != fixedpoint::PoseStatus::ok) {
    ++row.refused;
    return;
  }
  if constexpr (std::is_same_v<Built, fixedpoint::BlockResult>) {
    pose_reference::merge(row.worst, pose_reference::compare(built.block, expected));
  } else {
    pose_reference::merge(row.worst, pose_reference::compare(built, expected));
  }
}

}  // namespace

int main() {
  constexpr int poses_per_regime = 1 << 12;  // as test_pose_builders.cpp
  std::printf("| poses | matrix | worst error / largest entry | log2 | worst error, ulps | worst error / bound | refused |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|\n");
  for (const random_poses::Regime& regime : random_poses::regimes) {
    std::mt19937_64 rng(regime.seed);
    Row rows[8] = {{"mat4(look_at)", {}},     {"perspective", {}},         {"V * M", {}},
                   {"P * (V * M)", {}},       {"B * (P * (V * M))", {}},  {"block of P * (V * M)", {}},
                   {"block of B * (P * (V * M))", {}}, {"(P * mat4(V)) * M", {}}};
    for (int i = 0; i < poses_per_regime; ++i) {
      const random_poses::Built b = random_poses::build(random_poses::pose(rng, regime));
      add(rows[0], b.view, b.view_expected);
      add(rows[1], b.projection, b.projection_expected);
      add(rows[2], b.view_from_object, b.view_from_object_expected);
      add(rows[3], b.clip_from_object, b.clip_expected);
      add(rows[4], b.texture_from_object, b.texture_expected);
      add(rows[5], b.clip_block, b.clip_block_expected);
      add(rows[6], b.texture_block, b.texture_block_expected);
      add(rows[7], b.clip_left_to_right, b.clip_left_to_right_expected);
    }
    for (const Row& row : rows) {
      std::printf("| %s | %s | %.3e | %.2f | %.2f | %.3f | %d |\n", regime.name, row.name, row.worst.worst_relative,
                  std::log2(row.worst.worst_relative), row.worst.worst_ulps, row.worst.worst_bound_ratio, row.refused);
    }
  }
  std::printf("\n%d poses per regime (random_poses.hpp); refused: a status instead of a matrix "
              "(entries beyond 2^29, or beyond 2^13 for the pipeline's block).\n",
              poses_per_regime);
  return 0;
}
