// Everything a sweep leaves in its output folder:
//   sweep.csv            one row per configuration (csv_io.hpp)
//   report.html          fronts, pictures, per-pass counts, notes, every row
//   front.md             the same tables in Markdown (what docs/sweep/ commits)
//   pareto_<axis>.svg    cost against RMS error, one per measured cost axis
//   images/<row>-{fixed,diff}.png    the chosen points, re-rendered
//   images/float-<filter>.png        the float model's picture, one per texture filter
#pragma once

#include <cstddef>
#include <filesystem>

#include "scene/scene.hpp"
#include "sweep/sweep_result.hpp"

namespace spanlight::sweep {

// Throws std::runtime_error naming the file that could not be written.
void write_report(const std::filesystem::path& dir, const scene::Scene& scene, const SweepResult& result,
                  PixelFormat format, std::size_t pictures);

// Writes through a temporary file and a rename. Throws std::runtime_error.
void write_text_file(const std::filesystem::path& file, const std::string& text);

}  // namespace spanlight::sweep
