#include "sweep/report_files.hpp"

#include "compare/compare.hpp"
#include "float_model/float_model.hpp"
#include "prepare/prepare.hpp"
#include "prepare/render_fixed.hpp"
#include "sweep/csv_io.hpp"
#include "sweep/filter_override.hpp"
#include "sweep/reference_in_format.hpp"
#include "sweep/report_plots.hpp"
#include "sweep/report_tables.hpp"

namespace spanlight::sweep {
namespace {

void write_png(io::OutputFolder& out, const std::string& file, int width, int height, const std::vector<std::uint8_t>& rgb) {
  out.write(file, compare::png_bytes({width, height, rgb}));
}

// Re-renders a row's fixed and float frames (cheaper than keeping every frame of the sweep).
// The float picture is shown in the row's format (reference_in_format.hpp), as it is compared.
Picture picture_of(io::OutputFolder& out, const scene::Scene& scene, const SweepResult& r, std::size_t row) {
  const GridPoint& c = r.rows[row].point;
  const scene::Scene filtered = with_filter(scene, c.filter);
  const auto prepared = prepare::prepare_scene(filtered);
  const prepare::FixedFrame fixed = prepare::render_fixed(*prepared, c.knobs);
  float_model::FloatFrame reference = float_model::render_float(filtered);
  reference.rgb = reference_in_format(reference.rgb, c.knobs.format);
  const std::string stem = "images/" + std::to_string(row);
  // One float picture per filter: every row with that filter has the same reference.
  Picture p{row, stem + "-fixed.png", std::string("images/float-") + to_string(c.filter) + ".png", stem + "-diff.png"};
  write_png(out, p.fixed_png, fixed.width, fixed.height, fixed.rgb);
  if (!out.has_written(p.float_png)) write_png(out, p.float_png, reference.width, reference.height, reference.rgb);
  const io::Rgb8Image heat = compare::heat_map(compare::Rgb8View{fixed.width, fixed.height, fixed.rgb},
                                               compare::Rgb8View{reference.width, reference.height, reference.rgb});
  write_png(out, p.diff_png, heat.width, heat.height, heat.rgb);
  return p;
}

}  // namespace

void write_report(io::OutputFolder& out, const scene::Scene& scene, const SweepResult& r, std::size_t pictures) {
  out.remove_earlier_files_under("images");  // pictures of an earlier sweep would be stale
  out.write("sweep.csv", to_csv(r));
  std::vector<CostAxis> measured;
  for (CostAxis axis : {CostAxis::m7, CostAxis::m0plus, CostAxis::host}) {
    if (!has_cost(r, axis)) continue;
    measured.push_back(axis);
    out.write("pareto_" + std::string(axis_slug(axis)) + ".svg", pareto_svg(r, axis));
  }
  std::vector<Picture> shown;
  const CostAxis pictured = measured.empty() ? CostAxis::host : measured.front();  // M7 when measured
  for (std::size_t row : rows_to_picture(r, pictured, pictures))
    shown.push_back(picture_of(out, scene, r, row));
  out.write("report.html", html_report(r, shown));
  out.write("front.md", markdown_summary(r));
}

}  // namespace spanlight::sweep
