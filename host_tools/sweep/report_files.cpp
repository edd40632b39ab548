#include "sweep/report_files.hpp"

#include <fstream>
#include <stdexcept>

#include "compare/compare.hpp"
#include "float_model/float_model.hpp"
#include "prepare/prepare.hpp"
#include "sweep/csv_io.hpp"
#include "sweep/filter_override.hpp"
#include "sweep/report_plots.hpp"
#include "sweep/report_tables.hpp"

namespace spanlight::sweep {
namespace fs = std::filesystem;

void write_text_file(const fs::path& file, const std::string& text) {
  const fs::path temp = file.string() + ".partial";
  {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    if (!out.flush()) {
      std::error_code ignored;
      fs::remove(temp, ignored);
      throw std::runtime_error(file.string() + ": cannot write");
    }
  }
  fs::rename(temp, file);
}

namespace {

void write_png(const fs::path& file, int width, int height, const std::vector<std::uint8_t>& rgb) {
  std::string error;
  if (!compare::write_png_atomically(file, width, height, rgb, &error)) throw std::runtime_error(file.string() + ": " + error);
}

// Re-renders a row's fixed and float frames (cheaper than keeping every frame of the sweep).
Picture picture_of(const fs::path& dir, const scene::Scene& scene, const SweepResult& r, std::size_t row, PixelFormat format) {
  const SweepConfig& c = r.rows[row].config;
  const scene::Scene filtered = with_filter(scene, c.filter);
  const auto prepared = prepare::prepare_scene(filtered);
  const prepare::FixedFrame fixed = prepare::render_fixed(*prepared, to_fixed_options(c, format));
  const float_model::FloatFrame reference = float_model::render_float(filtered);
  const std::string stem = "images/" + std::to_string(row);
  // One float picture per filter: every row with that filter has the same reference.
  Picture p{row, stem + "-fixed.png", std::string("images/float-") + to_string(c.filter) + ".png", stem + "-diff.png"};
  write_png(dir / p.fixed_png, fixed.width, fixed.height, fixed.rgb);
  std::error_code ec;
  if (!fs::exists(dir / p.float_png, ec)) write_png(dir / p.float_png, reference.width, reference.height, reference.rgb);
  if (!compare::write_heat_map(compare::Rgb8View{fixed.width, fixed.height, fixed.rgb},
                               compare::Rgb8View{reference.width, reference.height, reference.rgb}, dir / p.diff_png))
    throw std::runtime_error((dir / p.diff_png).string() + ": cannot write");
  return p;
}

}  // namespace

void write_report(const fs::path& dir, const scene::Scene& scene, const SweepResult& r, PixelFormat format,
                  std::size_t pictures) {
  std::error_code ec;
  fs::remove_all(dir / "images", ec);  // pictures of an earlier sweep would be stale
  fs::create_directories(dir / "images", ec);
  if (ec) throw std::runtime_error((dir / "images").string() + ": cannot create: " + ec.message());
  write_text_file(dir / "sweep.csv", to_csv(r));
  std::vector<CostAxis> measured;
  for (CostAxis axis : {CostAxis::m7, CostAxis::m0plus, CostAxis::host}) {
    if (!has_cost(r, axis)) continue;
    measured.push_back(axis);
    write_text_file(dir / ("pareto_" + std::string(axis_slug(axis)) + ".svg"), pareto_svg(r, axis));
  }
  std::vector<Picture> shown;
  const CostAxis pictured = measured.empty() ? CostAxis::host : measured.front();  // M7 when measured
  for (std::size_t row : rows_to_picture(r, pictured, pictures))
    shown.push_back(picture_of(dir, scene, r, row, format));
  write_text_file(dir / "report.html", html_report(r, shown));
  write_text_file(dir / "front.md", markdown_summary(r));
}

}  // namespace spanlight::sweep
