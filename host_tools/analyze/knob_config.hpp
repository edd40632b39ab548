// A configuration as a JSON file: what `spanlight analyze --write-config`
// proposes and `spanlight bake --config` builds.
//   {"spanlight_knobs": 1, "span": 16, "tolerance": 3, "table_bits": 8,
//    "newton": 1, "depth_bits": 24, "format": "rgb888", "fused": false,
//    "texture_filter": "scene", "measured": {...}}
// "measured" (optional, ignored on reading) records why it was chosen.
#pragma once

#include <filesystem>
#include <string>

#include "sweep/sweep_config.hpp"

namespace spanlight::analyze {

struct KnobConfig {
  sweep::SweepConfig knobs;
  PixelFormat format = PixelFormat::rgb888;
};

std::string to_json(const KnobConfig& config, const std::string& measured_json = "{}");
// Throws std::runtime_error ("FILE: FIELD: expected ...") on a missing file, bad JSON or a bad value.
KnobConfig read_knob_config(const std::filesystem::path& file);

}  // namespace spanlight::analyze
