// A grid point as a JSON file: what `spanlight analyze --write-config` proposes
// and `spanlight bake --config` builds. Each knob of knob_table by its name and
// value as `spanlight render` takes it (numbers may be JSON numbers), plus the
// texture filter:
//   {"spanlight_knobs": 3, "span": 16, "tolerance": 5, "table-bits": 8, "newton": 1,
//    "depth-bits": 24, "format": "rgb888", "passes": "fused", "mip": "trilinear", "texture_filter": "scene",
//    "measured": {...}}
// "measured" (optional, ignored on reading) records why it was chosen.
#pragma once

#include <filesystem>
#include <string>

#include "sweep/grid.hpp"

namespace spanlight::analyze {

inline constexpr int knob_config_version = 3;

std::string to_json(const sweep::GridPoint& point, const std::string& measured_json = "{}");
// Throws std::runtime_error ("FILE: FIELD: expected ...") on a missing file, bad JSON or a bad value.
sweep::GridPoint read_knob_config(const std::filesystem::path& file);

}  // namespace spanlight::analyze
