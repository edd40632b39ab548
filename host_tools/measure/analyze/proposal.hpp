// The cheapest measured configuration that meets an accuracy target. Cost is
// the Cortex-M7 instruction count when the sweep measured it, else the
// Cortex-M0+ count, else host time; ties go to the smaller memory.
#pragma once

#include <optional>
#include <string>

#include "sweep/report_plots.hpp"
#include "sweep/sweep_result.hpp"

namespace spanlight::analyze {

struct AccuracyTarget {
  std::optional<double> max_error_lsb;  // every pixel's largest channel error <= this
  std::optional<double> min_psnr_db;
  // Neither given: at least as accurate (RMS) as the default configuration.
  std::string describe() const;
};

struct Constraints {
  int min_depth_bits = 16;            // from the format analysis
  bool allow_filter_change = false;   // else only filter "scene" (bake keeps the scene's filters)
};

struct Proposal {
  std::optional<std::size_t> row;     // index into the sweep's rows
  sweep::CostAxis axis = sweep::CostAxis::host;
  std::size_t candidates = 0;         // rows meeting the target and the constraints
  std::string why_none;
};

// Judged against the float model of the scene as authored (the *_vs_scene figures).
bool meets(const sweep::SweepRow& row, const AccuracyTarget& target, double default_rms);
Proposal cheapest_meeting(const sweep::SweepResult& result, const AccuracyTarget& target, const Constraints& constraints);

}  // namespace spanlight::analyze
