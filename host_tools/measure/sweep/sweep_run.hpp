// `spanlight sweep`: renders a scene over a grid of the pipeline's knobs and
// measures each configuration's accuracy (against the float model, on the
// image and on the interpolated coordinates), host time, instruction count on
// Cortex-M7 and Cortex-M0+ (QEMU, sweep_bench), and memory.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "sweep/progress.hpp"
#include "sweep/sweep_result.hpp"

namespace spanlight::sweep {

enum class QemuGrid {
  none,  // no QEMU runs: target cost n/a
  cost,  // table bits 8 and depth bits 24 only; the other table and depth settings reuse those counts
  full,  // every configuration
};

struct SweepOptions {
  GridSpec grid = default_grid();  // grid.filters empty: the scene's distinct choices (filter_override.hpp);
                                   // one format (the sweep_bench is built as baked)
  int host_repeats = 3;       // host times are the fastest of this many renders
  QemuGrid qemu = QemuGrid::cost;
  std::vector<std::string> cpus{"cortex-m7", "cortex-m0plus"};
  int jobs = 2;               // QEMU runs side by side
  bool per_pass = true;       // also count the default knobs pass by pass
  std::filesystem::path firmware_dir;  // the build tree with firmware-<cpu>/bin and the plugin
  std::filesystem::path measure_script;  // measure_elf.sh
};

// The grid's one pixel format; throws std::invalid_argument when it lists several.
PixelFormat grid_format(const GridSpec& grid);

// Throws prepare::PrepareError when the scene does not fit the fixed formats.
SweepResult run_sweep(const scene::Scene& scene, const SweepOptions& options, Progress& progress);

// Marks the Pareto fronts (M7, M0+, host time vs RMS error against the scene as
// authored) and the default knobs (of the grid's format).
void mark_fronts(SweepResult& result);

}  // namespace spanlight::sweep
