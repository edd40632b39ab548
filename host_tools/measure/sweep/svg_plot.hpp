// A cost-vs-error scatter plot as a standalone SVG string: every configuration
// as a dot, the Pareto front as larger dots joined by a staircase, highlighted
// points (e.g. the default configuration) ringed and labelled. No dependencies.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace spanlight::sweep {

enum class PointStyle { dominated, front, highlight };

struct ScatterPoint {
  double x, y;
  PointStyle style = PointStyle::dominated;
  std::string label;  // shown next to highlighted points; every point's <title> (hover text)
};

struct PlotSpec {
  std::string title, x_label, y_label;
  int width = 760, height = 480;
};

// "Nice" tick values (1, 2 or 5 times a power of ten) covering [lo, hi], about `count` of them.
std::vector<double> nice_ticks(double lo, double hi, int count);

// Maps [lo, hi] onto [out_lo, out_hi] (out_hi < out_lo for a y axis pointing up).
double scale(double value, double lo, double hi, double out_lo, double out_hi);

// &, <, >, " and ' escaped for SVG text and attributes.
std::string xml_escape(const std::string& text);

// The plot. Points with a NaN coordinate are skipped. Front points are joined
// in order of x by a staircase (the region they dominate).
std::string scatter_svg(const PlotSpec& spec, std::span<const ScatterPoint> points);

}  // namespace spanlight::sweep
