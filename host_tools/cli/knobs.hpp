// The pipeline's knobs (spanlight/knobs.hpp) as command-line options, made
// from the one knob table, for every command that runs the fixed pipeline.
#pragma once

#include <CLI/CLI.hpp>

#include "spanlight/knobs.hpp"

namespace spanlight::cli {

// Adds `--name value` for every knob of knob_table, writing into `knobs` (defaults shown in --help).
void add_knob_options(CLI::App& cmd, Knobs& knobs);

// The knob options' names as CLI11 knows them ("--span", ...), e.g. to exclude them together.
std::vector<std::string> knob_option_names();

}  // namespace spanlight::cli
