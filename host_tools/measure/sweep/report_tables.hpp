// The sweep's tables as Markdown (front.md, committed under docs/sweep/) and
// HTML (report.html): the Pareto front of each cost axis with the default's
// place, the default frame pass by pass, and the notes.
#pragma once

#include <string>
#include <vector>

#include "sweep/report_plots.hpp"
#include "sweep/sweep_result.hpp"

namespace spanlight::sweep {

// Human figures: 48.2 M, 1.02 k.
std::string millions(double instructions);

std::string markdown_summary(const SweepResult& result);

struct Picture {
  std::size_t row;
  std::string fixed_png, float_png, diff_png;  // relative to the report
};
std::string html_report(const SweepResult& result, const std::vector<Picture>& pictures);

}  // namespace spanlight::sweep
