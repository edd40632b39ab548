#include "sweep/sweep_run.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <thread>

#include "compare/compare.hpp"
#include "float_model/float_model.hpp"
#include "prepare/prepare.hpp"
#include "prepare/render_fixed.hpp"
#include "sweep/coordinate_map.hpp"
#include "sweep/filter_override.hpp"
#include "sweep/memory_cost.hpp"
#include "sweep/pareto.hpp"
#include "sweep/qemu_bench.hpp"
#include "sweep/reference_in_format.hpp"

namespace spanlight::sweep {
namespace {

using Clock = std::chrono::steady_clock;

template <typename Fn>
double fastest_ms(int repeats, Fn&& fn) {
  double best = INFINITY;
  for (int i = 0; i < std::max(repeats, 1); ++i) {
    const auto start = Clock::now();
    fn();
    best = std::min(best, std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  return best;
}

// Coordinates do not depend on the filter, the format or the passes: one probe per remaining knob set.
using ProbeKey = std::tuple<int, int, int, int, int>;
ProbeKey probe_key(const Knobs& k) { return {k.span_log2, k.tolerance_log2, k.table_bits, k.newton, k.depth_bits}; }

double rms_from_psnr(double psnr_db) { return std::isinf(psnr_db) ? 0.0 : 255.0 * std::pow(10.0, -psnr_db / 20.0); }

// --- host phase: accuracy and host time of every configuration

void measure_on_host(const scene::Scene& scene, const SweepOptions& o, SweepResult& result,
                     std::map<std::string, std::uint32_t>& hashes, Progress& progress) {
  const CoordinateMap reference = float_coordinates(scene);
  result.covered_pixels = static_cast<std::size_t>(std::count_if(reference.object.begin(), reference.object.end(), [](int v) { return v >= 0; }));
  std::vector<bool> textured;
  for (const scene::Object& object : scene.objects) textured.push_back(object.texture >= 0);

  std::map<ProbeKey, CoordinateError> probes;
  const float_model::FloatFrame authored = float_model::render_float(scene);
  progress.phase("host: accuracy and time", result.rows.size());
  const PixelFormat format = grid_format(o.grid);
  const std::vector<std::uint8_t> authored_rgb = reference_in_format(authored.rgb, format);
  FilterChoice prepared_for = FilterChoice::scene;
  std::unique_ptr<prepare::PreparedStorage> prepared;
  std::vector<std::uint8_t> reference_rgb;
  double float_ms = 0.0;
  for (SweepRow& row : result.rows) {
    const GridPoint& c = row.point;
    if (!prepared || c.filter != prepared_for) {  // rows are grouped by filter (expand)
      const scene::Scene filtered = with_filter(scene, c.filter);
      prepared = prepare::prepare_scene(filtered);
      prepared_for = c.filter;
      float_model::FloatFrame reference_frame;
      float_ms = fastest_ms(o.host_repeats, [&] { reference_frame = float_model::render_float(filtered); });
      reference_rgb = reference_in_format(reference_frame.rgb, format);
    }
    prepare::FixedFrame frame;
    row.host_ms = fastest_ms(o.host_repeats, [&] { frame = prepare::render_fixed(*prepared, c.knobs); });
    row.float_ms = float_ms;
    hashes[label(c)] = fnv1a(frame.raw);

    const compare::CompareResult diff = compare::compare_images(
        compare::Rgb8View{frame.width, frame.height, frame.rgb},
        compare::Rgb8View{frame.width, frame.height, reference_rgb});
    row.psnr_db = diff.psnr_db;
    row.rms_lsb = rms_from_psnr(diff.psnr_db);
    row.max_lsb = diff.max_abs_lsb;
    row.mean_lsb = diff.mean_abs_lsb;
    row.pct_over_2 = diff.pct_over_2_lsb;
    row.pct_over_8 = diff.pct_over_8_lsb;
    const compare::CompareResult vs_scene =
        c.filter == FilterChoice::scene ? diff
                                        : compare::compare_images(compare::Rgb8View{frame.width, frame.height, frame.rgb},
                                                                  compare::Rgb8View{authored.width, authored.height, authored_rgb});
    row.psnr_vs_scene_db = vs_scene.psnr_db;
    row.rms_vs_scene_lsb = rms_from_psnr(vs_scene.psnr_db);
    row.max_vs_scene_lsb = vs_scene.max_abs_lsb;

    auto probe = probes.find(probe_key(c.knobs));
    if (probe == probes.end())
      probe = probes.emplace(probe_key(c.knobs), compare_coordinates(fixed_coordinates(*prepared, c.knobs), reference, textured)).first;
    const CoordinateError& e = probe->second;
    row.uv_err_max = e.uv_max;
    row.uv_err_mean = e.uv_mean;
    row.st_err_max = e.st_max;
    row.st_err_mean = e.st_mean;
    row.visibility_mismatches = e.object_mismatches;

    row.table_bytes = table_bytes(c.knobs.table_bits);
    row.buffer_bytes = buffer_bytes(prepared->scene, c.knobs);
    char detail[160];
    std::snprintf(detail, sizeof detail, "%s: %.2f dB, max %.0f LSB, texels %.3f", label(c).c_str(), row.psnr_db,
                  row.max_lsb, row.texcoord_err_max());
    progress.step(detail);
  }
  progress.finish_phase();
}

// --- QEMU phase: instruction counts on each CPU

struct QemuTask {
  std::string cpu;
  GridPoint point;
  std::filesystem::path elf;
  BenchRun run;
};

void run_tasks(std::vector<QemuTask>& tasks, const MeasureSetup& setup, int jobs, Progress& progress) {
  std::atomic<std::size_t> next{0};
  std::mutex report;
  auto worker = [&] {
    for (std::size_t i = next++; i < tasks.size(); i = next++) {
      tasks[i].run = run_bench(setup, tasks[i].cpu, tasks[i].elf, tasks[i].point);
      const std::lock_guard<std::mutex> lock(report);
      const std::string count = tasks[i].run.ok ? std::to_string(tasks[i].run.instructions) + " instructions"
                                                : "failed: " + tasks[i].run.error;
      progress.step(tasks[i].cpu + " " + label(tasks[i].point) + ": " + count);
    }
  };
  std::vector<std::thread> threads;
  for (int j = 0; j < std::max(jobs, 1); ++j) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
}

void measure_on_qemu(const scene::Scene& scene, const SweepOptions& o, SweepResult& result,
                     const std::map<std::string, std::uint32_t>& hashes, Progress& progress) {
  auto mark_all = [&](const std::string& cpu, const std::string& why) {
    for (SweepRow& row : result.rows) (cpu == "cortex-m7" ? row.m7 : row.m0plus).source = "n/a: " + why;
  };
  if (o.qemu == QemuGrid::none) {
    for (const std::string& cpu : o.cpus) mark_all(cpu, "QEMU runs switched off (--qemu-grid none)");
    result.notes.push_back("Target cost not measured: --qemu-grid none.");
    return;
  }
  const MeasureSetup setup =
      find_measure_setup(o.firmware_dir / "tools" / "qemu_icount" / "libspanlight_icount.so", o.measure_script);
  std::vector<QemuTask> tasks;
  for (const std::string& cpu : o.cpus) {
    if (!setup.unavailable.empty()) {
      mark_all(cpu, setup.unavailable);
      result.notes.push_back(cpu + " cost n/a: " + setup.unavailable + ".");
      continue;
    }
    const std::filesystem::path elf = bench_elf(o.firmware_dir, cpu, scene.name);
    std::error_code ec;
    if (!std::filesystem::exists(elf, ec)) {
      mark_all(cpu, elf.filename().string() + " not built");
      result.notes.push_back(cpu + " cost n/a: " + elf.string() + " is missing (is the scene in "
                             "firmware/apps/render_baked/scenes.cmake, and was firmware-" + cpu + " built?).");
      continue;
    }
    std::vector<GridPoint> unique;
    for (const SweepRow& row : result.rows) {
      const GridPoint rep = o.qemu == QemuGrid::full ? row.point : cost_representative(row.point, o.grid);
      if (std::find(unique.begin(), unique.end(), rep) == unique.end()) unique.push_back(rep);
    }
    for (const GridPoint& c : unique) tasks.push_back({cpu, c, elf, {}});
    if (const auto flash = pipeline_flash(elf)) {
      for (SweepRow& row : result.rows)
        (cpu == "cortex-m7" ? row.flash_m7 : row.flash_m0plus) = flash->for_knobs(row.point.knobs);
    }
  }
  if (tasks.empty()) return;
  progress.phase("QEMU: instruction counts", tasks.size());
  run_tasks(tasks, setup, o.jobs, progress);
  progress.finish_phase();

  std::size_t mismatched = 0, failed = 0;
  for (SweepRow& row : result.rows) {
    bool any_run = false, all_same = true;  // hash_checked: every run behind this row's counts matched the host
    for (const std::string& cpu : o.cpus) {
      const GridPoint rep = o.qemu == QemuGrid::full ? row.point : cost_representative(row.point, o.grid);
      const auto task = std::find_if(tasks.begin(), tasks.end(), [&](const QemuTask& t) { return t.cpu == cpu && t.point == rep; });
      if (task == tasks.end()) continue;
      TargetCost& cost = cpu == "cortex-m7" ? row.m7 : row.m0plus;
      if (!task->run.ok) {
        cost.source = "n/a: " + task->run.error;
        ++failed;
        continue;
      }
      if (task->run.format != prepare::to_string(grid_format(o.grid))) {
        cost.source = "n/a: the bench is baked as " + task->run.format;
        ++failed;
        continue;
      }
      const auto hash = hashes.find(label(rep));
      const bool same_frame = hash != hashes.end() && hash->second == task->run.hash;
      if (!same_frame && rep == row.point) ++mismatched;
      any_run = true;
      all_same = all_same && same_frame;
      cost.instructions = task->run.instructions;
      cost.source = rep == row.point ? "measured" : "as " + label(rep);
    }
    row.hash_checked = any_run && all_same;
  }
  if (failed) result.notes.push_back(std::to_string(failed) + " target cost figure(s) n/a: a QEMU run failed (see the CSV's source column).");
  if (mismatched) result.notes.push_back(std::to_string(mismatched) + " QEMU run(s) rendered a frame whose hash differs from the host render's: the bench and the host disagree.");
  else result.notes.push_back("Every QEMU frame hash equals the host render's hash of the same configuration.");
  if (o.qemu == QemuGrid::cost)
    result.notes.push_back("QEMU ran the cost-relevant grid: the default table bits and depth bits only. Other table sizes and "
                           "depth bits run the same instructions with other constants and reuse those counts "
                           "(source \"as ...\"); they differ only where the values change a span's subdivision or a "
                           "depth test. --qemu-grid full measures every configuration.");

  if (!o.per_pass) return;
  GridPoint def;
  def.knobs.format = grid_format(o.grid);
  for (const std::string& cpu : o.cpus) {
    const std::filesystem::path elf = bench_elf(o.firmware_dir, cpu, scene.name);
    std::error_code ec;
    if (!setup.unavailable.empty() || !std::filesystem::exists(elf, ec)) continue;
    const BenchRun run = run_bench(setup, cpu, elf, def, true);
    if (!run.ok || run.regions.size() != run.region_names.size()) {
      result.notes.push_back(cpu + ": the per-pass count failed: " + (run.ok ? "region names and counts differ" : run.error));
      continue;
    }
    result.passes.push_back({cpu, run.region_names, run.regions});
  }
}

}  // namespace

PixelFormat grid_format(const GridSpec& grid) {
  const std::size_t format_index = [] {
    for (std::size_t i = 0; i < std::size(knob_table); ++i)
      if (std::string_view(knob_table[i].name) == "format") return i;
    return std::size_t{0};
  }();
  const std::vector<std::string>& formats = grid.values.at(format_index);
  if (formats.size() != 1)
    throw std::invalid_argument("--format: expected one format (the scene's sweep_bench is built in the one it was baked with)");
  Knobs k;
  if (set_knob(k, "format", formats.front()) != KnobError::ok)
    throw std::invalid_argument("--format: expected one of " + choice_list("format"));
  return k.format;
}

void mark_fronts(SweepResult& result) {
  auto mark = [&](auto cost_of, auto set) {
    std::vector<ParetoPoint> points;
    for (const SweepRow& row : result.rows) points.push_back({cost_of(row), row.rms_vs_scene_lsb});
    for (std::size_t i : pareto_front(points)) set(result.rows[i]);
  };
  mark([](const SweepRow& r) { return r.m7.instructions ? static_cast<double>(*r.m7.instructions) : NAN; },
       [](SweepRow& r) { r.front_m7 = true; });
  mark([](const SweepRow& r) { return r.m0plus.instructions ? static_cast<double>(*r.m0plus.instructions) : NAN; },
       [](SweepRow& r) { r.front_m0plus = true; });
  mark([](const SweepRow& r) { return r.host_ms; }, [](SweepRow& r) { r.front_host = true; });
  for (SweepRow& row : result.rows) {
    Knobs defaults;
    defaults.format = row.point.knobs.format;
    row.is_default = row.point == GridPoint{defaults, FilterChoice::scene};
  }
}

SweepResult run_sweep(const scene::Scene& scene, const SweepOptions& options, Progress& progress) {
  const auto start = Clock::now();
  SweepOptions o = options;
  if (o.grid.filters.empty()) o.grid.filters = distinct_filter_choices(scene);
  SweepResult result;
  result.scene_name = scene.name;
  result.scene_file = scene.file.string();
  check_grid(o.grid);
  result.format = prepare::to_string(grid_format(o.grid));
  result.width = scene.width;
  result.height = scene.height;
  for (const GridPoint& c : expand(o.grid)) {
    SweepRow row;
    row.point = c;
    result.rows.push_back(row);
  }

  std::map<std::string, std::uint32_t> hashes;
  measure_on_host(scene, o, result, hashes, progress);
  measure_on_qemu(scene, o, result, hashes, progress);
  mark_fronts(result);
  if (o.grid.filters.size() > 1 || o.grid.filters.front() != FilterChoice::scene)
    result.notes.push_back("Rows with a forced texture filter have two errors: against the float model rendering the "
                           "same forced filter (the pipeline's own error: PSNR, max, mean, % columns) and against the "
                           "float model of the scene as authored (\"vs authored\": what forcing the filter costs in "
                           "accuracy). The Pareto fronts use the RMS error against the scene as authored.");
  result.notes.push_back("Host times are the fastest of " + std::to_string(o.host_repeats) +
                         " renders on the machine that ran the sweep; only their ratio to the float model's is comparable.");
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace spanlight::sweep
