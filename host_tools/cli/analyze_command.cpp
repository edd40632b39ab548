// spanlight analyze SCENE.json [--max-error-lsb E | --min-psnr P] [--sweep-csv FILE]
//                  [--write-config FILE]
// What the scene needs (features, ranges, formats), then the cheapest measured
// configuration that meets the target, as a `spanlight bake` command line.
#include <cstdio>
#include <string>

#include "analyze/analysis_report.hpp"
#include "analyze/format_choice.hpp"
#include "analyze/knob_config.hpp"
#include "analyze/proposal.hpp"
#include "analyze/scene_ranges.hpp"
#include "cli/commands.hpp"
#include "cli/load.hpp"
#include "io/atomic_write.hpp"
#include "prepare/prepare.hpp"
#include "sweep/csv_io.hpp"
#include "io/knob_text.hpp"
#include "sweep/measurement.hpp"
#include "sweep/sweep_run.hpp"

namespace spanlight::cli {
namespace {

inline constexpr int exit_target_missed = 1;

struct AnalyzeArgs {
  std::string scene, sweep_csv, write_config, format = "rgb888", qemu_grid = "cost", firmware_dir;
  double max_error_lsb = -1.0, min_psnr = -1.0;
  bool allow_filter_change = false, quiet = false;
  int jobs = 2;
};

sweep::SweepResult measure(const scene::Scene& scene, const AnalyzeArgs& a) {
  if (!a.sweep_csv.empty()) return sweep::read_csv(a.sweep_csv);
  sweep::SweepOptions o;
  if (!a.allow_filter_change) o.grid.filters = {FilterChoice::scene};
  else o.grid.filters.clear();
  for (std::size_t i = 0; i < std::size(knob_table); ++i)
    if (std::string_view(knob_table[i].name) == "format") o.grid.values[i] = {a.format};
  o.qemu = a.qemu_grid == "none" ? sweep::QemuGrid::none : a.qemu_grid == "full" ? sweep::QemuGrid::full : sweep::QemuGrid::cost;
  o.jobs = a.jobs;
  o.per_pass = false;
  o.firmware_dir = a.firmware_dir.empty() ? sweep::default_build_dir() : std::filesystem::path(a.firmware_dir);
  o.measure_script = sweep::default_measure_script();
  sweep::Progress progress(stderr, a.quiet);
  sweep::SweepResult r = sweep::run_sweep(scene, o, progress);
  for (const std::string& note : r.notes) std::fprintf(stderr, "note: %s\n", note.c_str());  // also when quiet
  return r;
}

int run_analyze(const AnalyzeArgs& a) {
  const std::optional<scene::Scene> scene = load_or_report(a.scene);
  if (!scene) return exit_bad_input;
  io::RunInputs inputs = inputs_of(*scene);
  if (!a.sweep_csv.empty()) inputs.add(a.sweep_csv);
  if (!a.write_config.empty()) io::check_output_file(a.write_config, "--write-config", inputs);  // before sweeping
  const analyze::SceneRanges ranges = analyze::measure_ranges(*scene);
  const std::vector<analyze::FormatChoice> formats = analyze::choose_formats(ranges);
  std::printf("%s\n%s\n%s\n", analyze::features_text(*scene).c_str(), analyze::ranges_text(ranges).c_str(),
              analyze::formats_text(formats).c_str());
  std::fflush(stdout);  // the analysis first, then any complaint from prepare on stderr
  if (!prepare_or_report(*scene)) return exit_bad_input;  // the formats above say which range overflows

  analyze::AccuracyTarget target;
  if (a.max_error_lsb >= 0.0) target.max_error_lsb = a.max_error_lsb;
  if (a.min_psnr >= 0.0) target.min_psnr_db = a.min_psnr;
  analyze::Constraints constraints;
  constraints.min_depth_bits = analyze::required_depth_bits(formats);
  if (constraints.min_depth_bits == 0) {
    Knobs deepest;
    (void)set_knob(deepest, "depth-bits", knob_choices("depth-bits").back());
    std::printf("Depth: no depth setting resolves this scene everywhere; proposing %d bits.\n\n", deepest.depth_bits);
    constraints.min_depth_bits = deepest.depth_bits;
  }
  constraints.allow_filter_change = a.allow_filter_change;

  const sweep::SweepResult result = measure(*scene, a);
  const analyze::Proposal proposal = analyze::cheapest_meeting(result, target, constraints);
  std::printf("%s", analyze::proposal_text(result, proposal, target).c_str());
  if (!proposal.row) return exit_target_missed;

  const sweep::SweepRow& row = result.rows[*proposal.row];
  std::printf("\nBake it with:\n  %s\n", analyze::bake_command_line(a.scene, row.point.knobs).c_str());
  if (row.point.filter != FilterChoice::scene)
    std::printf("  (the proposal forces every texture to %s: bake --config applies that; a plain bake keeps the scene's filters)\n",
                sweep::to_string(row.point.filter));
  if (!a.write_config.empty()) {
    io::write_file_atomically(a.write_config, analyze::to_json(row.point, analyze::measured_json(result, row, target)),
                              "--write-config", inputs);
    std::printf("or:\n  spanlight bake %s --out baked/ --config %s\n", a.scene.c_str(), a.write_config.c_str());
  }
  return exit_ok;
}

}  // namespace

Command add_analyze_command(CLI::App& app) {
  auto a = std::make_shared<AnalyzeArgs>();
  CLI::App* cmd = app.add_subcommand("analyze", "what a scene needs (features, ranges, formats) and the cheapest "
                                                "configuration meeting an accuracy target");
  cmd->add_option("scene", a->scene, "scene file (JSON, see docs/scene-format.md)")->required();
  auto* max_error = cmd->add_option("--max-error-lsb", a->max_error_lsb, "largest error allowed at any pixel, 8-bit levels")
                        ->check(CLI::Range(0.0, 255.0));
  cmd->add_option("--min-psnr", a->min_psnr, "lowest PSNR allowed against the float model, dB")
      ->check(CLI::Range(0.0, 200.0))
      ->excludes(max_error);
  cmd->add_option("--sweep-csv", a->sweep_csv, "use the measurements of an earlier `spanlight sweep` (its sweep.csv) "
                                               "instead of sweeping now");
  cmd->add_option("--write-config", a->write_config,
                  "write the proposal as JSON for `spanlight bake --config` (a new file or a regular one to replace)");
  cmd->add_flag("--allow-filter-change", a->allow_filter_change, "also consider forcing every texture to one filter");
  cmd->add_option("--format", a->format, "framebuffer format (the scene's sweep_bench is built in the one it was baked with)")
      ->check(CLI::IsMember(knob_choices("format")));
  cmd->add_option("--qemu-grid", a->qemu_grid, "QEMU runs when sweeping: cost, full or none")
      ->check(CLI::IsMember({"cost", "full", "none"}));
  cmd->add_option("--firmware-dir", a->firmware_dir, "build tree with the sweep_bench ELFs (default: this binary's)");
  cmd->add_option("--jobs", a->jobs, "QEMU runs side by side")->check(CLI::Range(1, 64));
  cmd->add_flag("--quiet", a->quiet, "no progress on stderr");
  return [a] { return run_analyze(*a); };
}

}  // namespace spanlight::cli
