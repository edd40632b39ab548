#include "sweep/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "io/number_text.hpp"

namespace spanlight::sweep {
namespace {

constexpr int margin_left = 80, margin_right = 30, margin_top = 40, margin_bottom = 60;

std::string number(double v) { return io::number_text("%.1f", v); }

// A tick label without trailing zeros: 0.5, 2, 40.
std::string tick_label(double v) { return io::number_text("%g", v); }

struct Range {
  double lo, hi;
};

Range padded_range(std::span<const ScatterPoint> points, bool x_axis) {
  double lo = INFINITY, hi = -INFINITY;
  for (const ScatterPoint& p : points) {
    const double v = x_axis ? p.x : p.y;
    if (std::isnan(p.x) || std::isnan(p.y)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (!(lo <= hi)) return {0.0, 1.0};
  if (hi == lo) return {lo - 0.5 - std::fabs(lo) * 0.05, hi + 0.5 + std::fabs(hi) * 0.05};
  const double pad = (hi - lo) * 0.05;
  return {lo - pad, hi + pad};
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int count) {
  std::vector<double> ticks;
  if (!(hi > lo) || count < 1) return ticks;
  const double raw = (hi - lo) / count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * power;
    if (step >= raw) break;
  }
  for (double t = std::ceil(lo / step) * step; t <= hi + step * 1e-9; t += step)
    ticks.push_back(std::fabs(t) < step * 1e-9 ? 0.0 : t);
  return ticks;
}

double scale(double value, double lo, double hi, double out_lo, double out_hi) {
  return out_lo + (value - lo) / (hi - lo) * (out_hi - out_lo);
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string scatter_svg(const PlotSpec& spec, std::span<const ScatterPoint> points) {
  const Range xr = padded_range(points, true), yr = padded_range(points, false);
  const double left = margin_left, right = spec.width - margin_right;
  const double top = margin_top, bottom = spec.height - margin_bottom;
  auto px = [&](double x) { return scale(x, xr.lo, xr.hi, left, right); };
  auto py = [&](double y) { return scale(y, yr.lo, yr.hi, bottom, top); };

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << spec.width << "\" height=\"" << spec.height
      << "\" viewBox=\"0 0 " << spec.width << " " << spec.height << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << spec.width / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << xml_escape(spec.title)
      << "</text>\n";

  // Axes, grid and ticks.
  svg << "<g class=\"axes\" stroke=\"#888\">\n"
      << "<line x1=\"" << number(left) << "\" y1=\"" << number(bottom) << "\" x2=\"" << number(right) << "\" y2=\""
      << number(bottom) << "\"/>\n"
      << "<line x1=\"" << number(left) << "\" y1=\"" << number(top) << "\" x2=\"" << number(left) << "\" y2=\""
      << number(bottom) << "\"/>\n</g>\n<g class=\"ticks\">\n";
  for (double t : nice_ticks(xr.lo, xr.hi, 6)) {
    svg << "<line x1=\"" << number(px(t)) << "\" y1=\"" << number(top) << "\" x2=\"" << number(px(t)) << "\" y2=\""
        << number(bottom) << "\" stroke=\"#eee\"/><text x=\"" << number(px(t)) << "\" y=\"" << number(bottom + 16)
        << "\" text-anchor=\"middle\">" << tick_label(t) << "</text>\n";
  }
  for (double t : nice_ticks(yr.lo, yr.hi, 6)) {
    svg << "<line x1=\"" << number(left) << "\" y1=\"" << number(py(t)) << "\" x2=\"" << number(right) << "\" y2=\""
        << number(py(t)) << "\" stroke=\"#eee\"/><text x=\"" << number(left - 6) << "\" y=\"" << number(py(t) + 4)
        << "\" text-anchor=\"end\">" << tick_label(t) << "</text>\n";
  }
  svg << "</g>\n<text x=\"" << number((left + right) / 2) << "\" y=\"" << spec.height - 18
      << "\" text-anchor=\"middle\">" << xml_escape(spec.x_label) << "</text>\n"
      << "<text transform=\"translate(18 " << number((top + bottom) / 2) << ") rotate(-90)\" text-anchor=\"middle\">"
      << xml_escape(spec.y_label) << "</text>\n";

  // The front as a staircase: right along the cost axis, then down to the next point.
  std::vector<const ScatterPoint*> front;
  for (const ScatterPoint& p : points)
    if (p.style == PointStyle::front && !std::isnan(p.x) && !std::isnan(p.y)) front.push_back(&p);
  std::sort(front.begin(), front.end(), [](const ScatterPoint* a, const ScatterPoint* b) { return a->x < b->x; });
  if (!front.empty()) {
    svg << "<polyline class=\"front\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.5\" points=\"";
    for (std::size_t i = 0; i < front.size(); ++i) {
      if (i > 0) svg << number(px(front[i]->x)) << "," << number(py(front[i - 1]->y)) << " ";
      svg << number(px(front[i]->x)) << "," << number(py(front[i]->y)) << " ";
    }
    svg << "\"/>\n";
  }

  // Dominated points first, so front and highlighted points are drawn on top.
  for (PointStyle layer : {PointStyle::dominated, PointStyle::front, PointStyle::highlight}) {
    for (const ScatterPoint& p : points) {
      if (p.style != layer || std::isnan(p.x) || std::isnan(p.y)) continue;
      const std::string cx = number(px(p.x)), cy = number(py(p.y));
      const char* attributes = layer == PointStyle::dominated ? "r=\"3\" fill=\"#9aa7b8\""
                               : layer == PointStyle::front   ? "r=\"4.5\" fill=\"#d62728\""
                                                              : "r=\"7\" fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"2.5\"";
      svg << "<circle class=\"" << (layer == PointStyle::dominated ? "dominated" : layer == PointStyle::front ? "front" : "highlight")
          << "\" cx=\"" << cx << "\" cy=\"" << cy << "\" " << attributes << "><title>" << xml_escape(p.label)
          << "</title></circle>\n";
      if (layer == PointStyle::highlight && !p.label.empty())
        svg << "<text x=\"" << number(px(p.x) + 10) << "\" y=\"" << number(py(p.y) - 8) << "\" fill=\"#1f77b4\">"
            << xml_escape(p.label) << "</text>\n";
    }
  }
  svg << "<g font-size=\"11\" transform=\"translate(" << number(right - 190) << " " << number(top + 4) << ")\">\n"
      << "<circle cx=\"6\" cy=\"0\" r=\"3\" fill=\"#9aa7b8\"/><text x=\"16\" y=\"4\">configuration</text>\n"
      << "<circle cx=\"6\" cy=\"16\" r=\"4.5\" fill=\"#d62728\"/><text x=\"16\" y=\"20\">Pareto front</text>\n"
      << "<circle cx=\"6\" cy=\"32\" r=\"7\" fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"2.5\"/>"
      << "<text x=\"16\" y=\"36\">highlighted</text>\n</g>\n</svg>\n";
  return svg.str();
}

}  // namespace spanlight::sweep
