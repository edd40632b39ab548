// The sweep's CSV: one row per configuration, one column per figure (header
// in csv_columns()). Not-measured figures are "n/a"; identical images have
// psnr_db "inf". No field holds a comma, so no quoting is needed.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sweep/sweep_result.hpp"

namespace spanlight::sweep {

std::vector<std::string> csv_columns();
std::string to_csv(const SweepResult& result);

// Reads a CSV written by to_csv back (rows and the scene's figures; notes and
// per-pass counts are not in the CSV). Throws std::runtime_error naming the
// file and line on anything else.
SweepResult read_csv(const std::filesystem::path& file);

}  // namespace spanlight::sweep
