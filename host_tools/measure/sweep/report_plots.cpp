#include "sweep/report_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sweep/pareto.hpp"
#include "sweep/svg_plot.hpp"

namespace spanlight::sweep {

const char* axis_name(CostAxis a) { return a == CostAxis::m7 ? "Cortex-M7" : a == CostAxis::m0plus ? "Cortex-M0+" : "host"; }
const char* axis_slug(CostAxis a) { return a == CostAxis::m7 ? "m7" : a == CostAxis::m0plus ? "m0plus" : "host"; }

std::optional<double> cost_of(const SweepRow& row, CostAxis a) {
  if (a == CostAxis::host) return row.host_ms;
  const TargetCost& cost = a == CostAxis::m7 ? row.m7 : row.m0plus;
  if (!cost.instructions) return std::nullopt;
  return static_cast<double>(*cost.instructions);
}

bool on_front(const SweepRow& row, CostAxis a) {
  return a == CostAxis::m7 ? row.front_m7 : a == CostAxis::m0plus ? row.front_m0plus : row.front_host;
}

bool has_cost(const SweepResult& r, CostAxis a) {
  return std::any_of(r.rows.begin(), r.rows.end(), [&](const SweepRow& row) { return cost_of(row, a).has_value(); });
}

std::vector<std::size_t> front_rows(const SweepResult& r, CostAxis a) {
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < r.rows.size(); ++i)
    if (on_front(r.rows[i], a)) rows.push_back(i);
  std::sort(rows.begin(), rows.end(), [&](std::size_t x, std::size_t y) { return *cost_of(r.rows[x], a) < *cost_of(r.rows[y], a); });
  return rows;
}

std::optional<std::size_t> default_row(const SweepResult& r) {
  for (std::size_t i = 0; i < r.rows.size(); ++i)
    if (r.rows[i].is_default) return i;
  return std::nullopt;
}

std::vector<std::size_t> rows_to_picture(const SweepResult& r, CostAxis a, std::size_t count) {
  const std::vector<std::size_t> front = front_rows(r, a);
  std::vector<std::size_t> chosen;
  const std::size_t n = std::min(count, front.size());
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t at = n == 1 ? 0 : k * (front.size() - 1) / (n - 1);  // evenly along the front
    if (std::find(chosen.begin(), chosen.end(), front[at]) == chosen.end()) chosen.push_back(front[at]);
  }
  if (const auto d = default_row(r); d && std::find(chosen.begin(), chosen.end(), *d) == chosen.end()) chosen.push_back(*d);
  return chosen;
}

std::string pareto_svg(const SweepResult& r, CostAxis a) {
  const bool instructions = a != CostAxis::host;
  const double unit = instructions ? 1e6 : 1.0;
  std::vector<ScatterPoint> points;
  for (const SweepRow& row : r.rows) {
    const std::optional<double> cost = cost_of(row, a);
    if (!cost) continue;
    char text[200];
    std::snprintf(text, sizeof text, "%s: %.3g %s, RMS %.3f LSB, PSNR %.2f dB", label(row.point).c_str(), *cost / unit,
                  instructions ? "M instructions" : "ms", row.rms_vs_scene_lsb, row.psnr_vs_scene_db);
    points.push_back({*cost / unit, row.rms_vs_scene_lsb, on_front(row, a) ? PointStyle::front : PointStyle::dominated, text});
    if (row.is_default)
      points.push_back({*cost / unit, row.rms_vs_scene_lsb, PointStyle::highlight, "default (" + label(row.point) + ")"});
  }
  PlotSpec spec;
  spec.title = r.scene_name + ": cost on " + axis_name(a) + " against error (Pareto front in red)";
  spec.x_label = instructions ? std::string("instructions per frame on ") + axis_name(a) + " (millions, QEMU)"
                              : std::string("host time per frame (ms)");
  spec.y_label = "RMS error against the float model of the scene (8-bit levels)";
  return scatter_svg(spec, points);
}

std::string default_place(const SweepResult& r, CostAxis a) {
  const std::optional<std::size_t> d = default_row(r);
  if (!d) return "The default configuration is not in this grid.";
  const SweepRow& def = r.rows[*d];
  const std::optional<double> def_cost = cost_of(def, a);
  if (!def_cost) return "The default configuration has no cost on this axis.";
  char text[400];
  if (on_front(def, a)) {
    std::snprintf(text, sizeof text, "The default (%s) is on the front.", label(def.point).c_str());
    return text;
  }
  // The cheapest front point at least as accurate as the default.
  for (std::size_t i : front_rows(r, a)) {
    const SweepRow& row = r.rows[i];
    if (row.rms_vs_scene_lsb <= def.rms_vs_scene_lsb) {
      const double saving = 100.0 * (1.0 - *cost_of(row, a) / *def_cost);
      std::snprintf(text, sizeof text,
                    "The default (%s) is off the front: %s is at least as accurate (RMS %.3f vs %.3f LSB) and %.1f%% cheaper.",
                    label(def.point).c_str(), label(row.point).c_str(), row.rms_vs_scene_lsb, def.rms_vs_scene_lsb, saving);
      return text;
    }
  }
  return "The default is off the front.";
}

}  // namespace spanlight::sweep
