// What the sweep records per configuration, and for the scene as a whole.
// Optional figures are "n/a" in the CSV: not measured, and the notes say why.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "sweep/grid.hpp"

namespace spanlight::sweep {

struct TargetCost {
  std::optional<std::uint64_t> instructions;  // per frame, exact (QEMU plugin)
  std::string source;  // "measured", "as <label>" (same code, see notes), or "n/a: why"
};

struct SweepRow {
  GridPoint point;
  // Accuracy against the float model, 8-bit levels (compare.hpp definitions); an RGB565
  // frame against the float picture rounded to RGB565 (reference_in_format.hpp).
  double psnr_db = 0.0;  // +inf when identical
  double rms_lsb = 0.0;  // 255 * 10^(-psnr/20): the error axis of the Pareto front
  double max_lsb = 0.0, mean_lsb = 0.0, pct_over_2 = 0.0, pct_over_8 = 0.0;
  // Against the float model of the scene as authored: differs from the above only
  // where the row forces a texture filter. The Pareto fronts use this RMS.
  double psnr_vs_scene_db = 0.0, rms_vs_scene_lsb = 0.0, max_vs_scene_lsb = 0.0;
  // Interpolated coordinates against the float model's exact values, in texels.
  double uv_err_max = 0.0, uv_err_mean = 0.0, st_err_max = 0.0, st_err_mean = 0.0;
  std::size_t visibility_mismatches = 0;  // pixels where the two show different objects
  // Host time, the fastest of the repeats, and its ratio to the float model's.
  double host_ms = 0.0, float_ms = 0.0;
  // Target cost.
  TargetCost m7, m0plus;
  bool hash_checked = false;  // the bench's frame hash equalled the host render's
  // Memory.
  std::size_t table_bytes = 0, buffer_bytes = 0;
  std::optional<std::size_t> flash_m7, flash_m0plus;
  // Place.
  bool is_default = false, front_m7 = false, front_m0plus = false, front_host = false;

  double host_ratio() const { return float_ms > 0.0 ? host_ms / float_ms : 0.0; }
  double texcoord_err_max() const { return uv_err_max > st_err_max ? uv_err_max : st_err_max; }
};

// A per-pass instruction count of the default knobs on one CPU.
struct PassCost {
  std::string cpu;
  std::vector<std::string> names;
  std::vector<std::uint64_t> instructions;
};

struct SweepResult {
  std::string scene_name, scene_file, format;
  int width = 0, height = 0;
  std::size_t covered_pixels = 0;  // pixels the float model covers in the eye view
  std::vector<SweepRow> rows;
  std::vector<PassCost> passes;    // the default knobs, pass by pass
  std::vector<std::string> notes;  // what was not measured and why, what was assumed
  double seconds = 0.0;            // wall time of the sweep
};

}  // namespace spanlight::sweep
