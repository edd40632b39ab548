// The pipeline's speed/accuracy knobs as command-line options, shared by
// render, bake and the other commands that run the fixed pipeline.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "prepare/render_fixed.hpp"

namespace spanlight::cli {

struct KnobArgs {
  int span = 16;
  int tolerance_log2 = 3;
  int table_bits = 8;
  int newton = 1;
  int depth_bits = 24;
  std::string format = "rgb888";
  bool fused = false;
};

void add_knob_options(CLI::App& cmd, KnobArgs& knobs);
prepare::FixedOptions to_fixed_options(const KnobArgs& knobs);

}  // namespace spanlight::cli
