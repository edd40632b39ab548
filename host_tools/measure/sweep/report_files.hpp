// Everything a sweep leaves in its output folder:
//   sweep.csv            one row per configuration (csv_io.hpp)
//   report.html          fronts, pictures, per-pass counts, notes, every row
//   front.md             the same tables in Markdown (what docs/sweep/ commits)
//   pareto_<axis>.svg    cost against RMS error, one per measured cost axis
//   images/<row>-{fixed,diff}.png    the chosen points, re-rendered
//   images/float-<filter>.png        the float model's picture, one per texture filter
#pragma once

#include <cstddef>

#include "io/output_folder.hpp"
#include "scene/scene.hpp"
#include "sweep/sweep_result.hpp"

namespace spanlight::sweep {

// Writes them into `out` (io::OutputFolder: a new folder, or one holding only
// what spanlight wrote; pictures of an earlier sweep there are removed first).
// Throws io::OutputError naming the file that could not be written.
void write_report(io::OutputFolder& out, const scene::Scene& scene, const SweepResult& result, std::size_t pictures);

}  // namespace spanlight::sweep
