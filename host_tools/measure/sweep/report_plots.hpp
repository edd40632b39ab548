// The report's view of a sweep: which cost axis, which rows are on its front,
// which rows to show as pictures, and the plot of each axis.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sweep/sweep_result.hpp"

namespace spanlight::sweep {

enum class CostAxis { m7, m0plus, host };

const char* axis_name(CostAxis axis);   // "Cortex-M7", "Cortex-M0+", "host"
const char* axis_slug(CostAxis axis);   // "m7", "m0plus", "host" (file names)
std::optional<double> cost_of(const SweepRow& row, CostAxis axis);  // instructions, or host ms
bool on_front(const SweepRow& row, CostAxis axis);
bool has_cost(const SweepResult& result, CostAxis axis);  // some row measured on this axis

// Row indices of the front, cheapest first.
std::vector<std::size_t> front_rows(const SweepResult& result, CostAxis axis);
std::optional<std::size_t> default_row(const SweepResult& result);

// At most `count` front rows spread from cheapest to most accurate, plus the default.
std::vector<std::size_t> rows_to_picture(const SweepResult& result, CostAxis axis, std::size_t count);

// Cost (millions of instructions, or ms) against RMS error (LSB), SVG.
std::string pareto_svg(const SweepResult& result, CostAxis axis);

// One sentence on where the default configuration sits relative to the front.
std::string default_place(const SweepResult& result, CostAxis axis);

}  // namespace spanlight::sweep
