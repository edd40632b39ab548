// spanlight sweep SCENE.json --out DIR [grid and measurement options]
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/load.hpp"
#include "io/output_folder.hpp"
#include "prepare/prepare.hpp"
#include "io/knob_text.hpp"
#include "sweep/measurement.hpp"
#include "sweep/report_files.hpp"
#include "sweep/report_plots.hpp"
#include "sweep/report_tables.hpp"
#include "sweep/sweep_run.hpp"

namespace spanlight::cli {
namespace {

struct SweepArgs {
  std::string scene, out;
  sweep::GridSpec grid = sweep::default_grid();  // the knob options replace a knob's list
  std::vector<std::string> filters{"all"};
  std::string qemu_grid = "cost", firmware_dir, measure_script;
  std::vector<std::string> cpus{"cortex-m7", "cortex-m0plus"};
  int repeats = 3, jobs = 2, pictures = 4;
  bool no_per_pass = false, quiet = false, force = false;
};

// --filters' words: all, then every FilterChoice (spanlight/knobs.hpp).
std::vector<std::string> filter_words() {
  std::vector<std::string> words{"all"};
  words.insert(words.end(), std::begin(knob_values::filter), std::end(knob_values::filter));
  return words;
}

sweep::SweepOptions to_options(const SweepArgs& a) {
  sweep::SweepOptions o;
  o.grid = a.grid;
  o.grid.filters.clear();  // empty: the scene's distinct choices
  for (const std::string& f : a.filters)
    if (f != "all") o.grid.filters.push_back(sweep::filter_from_string(f));
  o.host_repeats = a.repeats;
  o.qemu = a.qemu_grid == "none" ? sweep::QemuGrid::none : a.qemu_grid == "full" ? sweep::QemuGrid::full : sweep::QemuGrid::cost;
  o.cpus = a.cpus;
  o.jobs = a.jobs;
  o.per_pass = !a.no_per_pass;
  o.firmware_dir = a.firmware_dir.empty() ? sweep::default_build_dir() : std::filesystem::path(a.firmware_dir);
  o.measure_script = a.measure_script.empty() ? sweep::default_measure_script() : std::filesystem::path(a.measure_script);
  return o;
}

int run_sweep_command(const SweepArgs& a) {
  const std::optional<scene::Scene> scene = load_or_report(a.scene);
  if (!scene) return exit_bad_input;
  if (!prepare_or_report(*scene)) return exit_bad_input;  // reports a scene the fixed formats cannot hold
  const sweep::SweepOptions options = to_options(a);
  try {
    (void)sweep::grid_format(options.grid);  // one format: the bench's
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "%s: %s\n", a.scene.c_str(), e.what());
    return exit_bad_input;
  }
  io::OutputFolder out(a.out, "--out", a.force, inputs_of(*scene));  // checked before the sweep's minutes of work
  sweep::Progress progress(stderr, a.quiet);
  const sweep::SweepResult result = sweep::run_sweep(*scene, options, progress);
  for (const std::string& note : result.notes) std::fprintf(stderr, "note: %s\n", note.c_str());  // also when quiet
  sweep::write_report(out, *scene, result, static_cast<std::size_t>(a.pictures));

  std::printf("swept %s: %zu configurations in %.0f s -> %s/{sweep.csv,report.html,front.md}\n", result.scene_name.c_str(),
              result.rows.size(), result.seconds, a.out.c_str());
  for (sweep::CostAxis axis : {sweep::CostAxis::m7, sweep::CostAxis::m0plus, sweep::CostAxis::host}) {
    if (!sweep::has_cost(result, axis)) continue;
    std::printf("%s: %zu point(s) on the front. %s\n", sweep::axis_name(axis), sweep::front_rows(result, axis).size(),
                sweep::default_place(result, axis).c_str());
  }
  return exit_ok;
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto a = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand("sweep", "render a scene over a grid of knobs; record accuracy, cost and memory");
  cmd->add_option("scene", a->scene, "scene file (JSON, see docs/scene-format.md)")->required();
  cmd->add_option("--out", a->out,
                  "output folder (sweep.csv, report.html, front.md, SVG plots, images/): new, empty, or holding only "
                  "what spanlight wrote there")
      ->required();
  cmd->add_flag("--force", a->force, "write into --out even when it holds other files (none is removed)");
  // Every knob of knob_table as a comma-separated list of its values, e.g. --span 4,16 --passes fused,multipass.
  for (std::size_t i = 0; i < std::size(knob_table); ++i) {
    const KnobInfo& info = knob_table[i];
    std::string defaults;
    for (const std::string& v : a->grid.values[i]) defaults += (defaults.empty() ? "" : ",") + v;
    const bool format = std::string_view(info.name) == "format";  // one: the sweep_bench is built in the baked format
    cmd->add_option("--" + std::string(info.name), a->grid.values[i],
                    std::string(info.help) + (format ? " (one: the format the scene's sweep_bench was baked in)" : " (values to sweep)"))
        ->check(CLI::IsMember(knob_choices(info.name)))
        ->delimiter(',')
        ->default_str(defaults);
  }
  cmd->add_option("--filters", a->filters,
                  "texture filters: scene (as the scene says), nearest or bilinear (forced on every texture), "
                  "all (scene plus each forced filter that changes the scene)")
      ->check(CLI::IsMember(filter_words()))->delimiter(',');
  cmd->add_option("--repeats", a->repeats, "host renders per configuration; the fastest counts")->check(CLI::Range(1, 50));
  cmd->add_option("--qemu-grid", a->qemu_grid,
                  "QEMU runs: cost (the default table and depth bits only, reused for the rest), full, or none")
      ->check(CLI::IsMember({"cost", "full", "none"}));
  cmd->add_option("--cpus", a->cpus, "QEMU targets")->check(CLI::IsMember({"cortex-m7", "cortex-m0plus"}))->delimiter(',');
  cmd->add_option("--jobs", a->jobs, "QEMU runs side by side")->check(CLI::Range(1, 64));
  cmd->add_option("--firmware-dir", a->firmware_dir,
                  "build tree holding firmware-<cpu>/bin/sweep_bench_<scene>.elf and the QEMU plugin "
                  "(default: the build tree of this binary)");
  cmd->add_option("--measure-script", a->measure_script, "measure_elf.sh (default: the one in this binary's source tree)");
  cmd->add_option("--pictures", a->pictures, "front points shown as fixed/float/difference images")->check(CLI::Range(0, 32));
  cmd->add_flag("--no-per-pass", a->no_per_pass, "skip the per-pass count of the default knobs");
  cmd->add_flag("--quiet", a->quiet, "no progress on stderr");
  return [a] { return run_sweep_command(*a); };
}

}  // namespace spanlight::cli
