// spanlight cost SCENE.json [knobs] [--cpu cortex-m7,cortex-m4,cortex-m0plus] [--jobs N]
// What a scene costs on target, without editing any CMake file: for each core, a
// scratch cross build of this source tree bakes the scene into render_cost (render_baked's
// source) with this very binary, measure_elf.sh runs it in QEMU, and a table says
// instructions per frame and per covered pixel, pipeline flash, RAM and stack peak.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "io/knob_text.hpp"
#include "cli/accuracy_warning.hpp"
#include "cli/commands.hpp"
#include "cli/knobs.hpp"
#include "cli/load.hpp"
#include "sweep/measurement.hpp"

namespace spanlight::cli {
namespace {
namespace fs = std::filesystem;

inline constexpr int exit_not_measured = 1;

struct CostArgs {
  std::string scene;
  Knobs knobs;
  std::vector<std::string> cpus{"cortex-m7", "cortex-m4", "cortex-m0plus"};
  int jobs = 2;
};

// A scratch folder of its own under the temporary directory, removed when done.
struct ScratchFolder {
  fs::path path;
  ScratchFolder() {
    std::string pattern = (fs::temp_directory_path() / "spanlight-cost-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot create a scratch folder in " + fs::temp_directory_path().string());
    path = pattern;
  }
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
};

// Runs a shell command with its output in `log`; true on exit status 0.
bool run_logged(const std::string& command, const fs::path& log) {
  return std::system((command + " > " + sweep::shell_quoted(log.string()) + " 2>&1").c_str()) == 0;
}

// The last lines of a log, for a failure message.
void print_tail(const fs::path& log) {
  if (std::system(("tail -n 20 " + sweep::shell_quoted(log.string()) + " >&2").c_str()) != 0) std::fprintf(stderr, "(see %s)\n", log.c_str());
}

struct CoreCost {
  std::string cpu;
  sweep::Measurement m;
};

std::string cmake_list(const std::vector<std::string>& words) {
  std::string list;
  for (const std::string& w : words) list += (list.empty() ? "" : ";") + w;
  return list;
}

int run_cost(const CostArgs& a) {
  const std::optional<scene::Scene> scene = load_or_report(a.scene);
  if (!scene) return exit_bad_input;
  if (!prepare_or_report(*scene)) return exit_bad_input;  // the firmware would refuse it too: say so now
  warn_if_inaccurate(a.knobs);
  const fs::path build_dir = sweep::default_build_dir();
  const sweep::MeasureSetup setup = sweep::find_measure_setup(build_dir / "tools" / "qemu_icount" / "libspanlight_icount.so",
                                                              sweep::default_measure_script());
  if (!setup.unavailable.empty()) {
    std::fprintf(stderr, "spanlight cost: cannot measure: %s\n", setup.unavailable.c_str());
    return exit_not_measured;
  }
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  const fs::path source = sweep::source_dir();
  ScratchFolder scratch;
  std::vector<CoreCost> costs;
  for (const std::string& cpu : a.cpus) {
    const fs::path tree = scratch.path / cpu;
    const fs::path log = scratch.path / (cpu + ".log");
    std::fprintf(stderr, "cost: %s: configuring a cross build\n", cpu.c_str());
    const std::string configure =
        "cmake -S " + sweep::shell_quoted(source.string()) + " -B " + sweep::shell_quoted(tree.string()) + " -G Ninja" +
        " -DCMAKE_TOOLCHAIN_FILE=" + sweep::shell_quoted((source / "hal" / "cortex_m" / "arm-none-eabi.cmake").string()) +
        " -DSPANLIGHT_CPU=" + cpu + " -DCMAKE_BUILD_TYPE=Release -DSPANLIGHT_INSTALL=OFF" +
        " -DSPANLIGHT_EXECUTABLE=" + sweep::shell_quoted(self.string()) +
        " -DSPANLIGHT_COST_SCENE=" + sweep::shell_quoted(fs::absolute(a.scene).string()) +
        " -DSPANLIGHT_COST_KNOBS=" + sweep::shell_quoted(cmake_list(knob_arguments(a.knobs)));
    if (!run_logged(configure, log)) {
      std::fprintf(stderr, "spanlight cost: %s: configuring the cross build failed:\n", cpu.c_str());
      print_tail(log);
      return exit_not_measured;
    }
    std::fprintf(stderr, "cost: %s: baking and building render_cost\n", cpu.c_str());
    if (!run_logged("cmake --build " + sweep::shell_quoted(tree.string()) + " --target render_cost -j " + std::to_string(a.jobs), log)) {
      std::fprintf(stderr, "spanlight cost: %s: building render_cost failed:\n", cpu.c_str());
      print_tail(log);
      return exit_not_measured;
    }
    std::fprintf(stderr, "cost: %s: running it in QEMU\n", cpu.c_str());
    const sweep::MeasureRun run = sweep::measure_elf(setup, cpu, tree / "bin" / "render_cost.elf", {"frame.ppm"}, tree);
    if (run.exit_code != 0 || !run.measurement) {
      std::fprintf(stderr, "spanlight cost: %s: the run failed (exit status %d):\n%s", cpu.c_str(), run.exit_code, run.log.c_str());
      return exit_not_measured;
    }
    costs.push_back({cpu, *run.measurement});
  }

  std::printf("%s with %s\n\n", scene->name.c_str(), knob_command_line(a.knobs).c_str());
  std::printf("| core | instructions/frame | covered px | per covered px | pipeline flash B | RAM B | stack peak B |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
  for (const CoreCost& c : costs) {
    const std::uint64_t covered = c.m.covered_pixels.value_or(0);
    const std::string per_pixel = covered ? std::to_string((c.m.instructions + covered / 2) / covered) : "n/a";
    std::printf("| %s | %llu | %llu | %s | %llu | %llu | %s |\n", c.cpu.c_str(), static_cast<unsigned long long>(c.m.instructions),
                static_cast<unsigned long long>(covered), per_pixel.c_str(), static_cast<unsigned long long>(c.m.pipeline_flash),
                static_cast<unsigned long long>(c.m.ram),
                c.m.stack_peak ? std::to_string(*c.m.stack_peak).c_str() : "n/a");
  }
  std::printf("\nExact QEMU counts of one render_frame call; pipeline flash = .text + .rodata + .data without the\n"
              "scene's data (namespace baked); RAM = .data + .bss without the stack reserve.\n");
  return exit_ok;
}

}  // namespace

Command add_cost_command(CLI::App& app) {
  auto a = std::make_shared<CostArgs>();
  CLI::App* cmd = app.add_subcommand("cost", "measure a scene on Cortex-M in QEMU: instructions per frame and per covered "
                                             "pixel, pipeline flash, RAM, stack peak");
  cmd->add_option("scene", a->scene, "scene file (JSON, see docs/scene-format.md)")->required();
  add_knob_options(*cmd, a->knobs);
  cmd->add_option("--cpu", a->cpus, "cores to measure, comma-separated")
      ->check(CLI::IsMember({"cortex-m7", "cortex-m4", "cortex-m0plus"}))
      ->delimiter(',');
  cmd->add_option("--jobs", a->jobs, "parallel compile jobs of each cross build")->check(CLI::Range(1, 64));
  return [a] { return run_cost(*a); };
}

}  // namespace spanlight::cli
