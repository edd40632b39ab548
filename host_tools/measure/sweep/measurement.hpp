// Running a firmware ELF through tools/qemu_icount/measure_elf.sh (the one
// measuring path) and reading its `spanlight-measure: KEY VALUE` lines.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace spanlight::sweep {

struct Measurement {
  std::uint64_t instructions = 0;        // summed over the measured regions
  std::vector<std::uint64_t> regions;    // each region
  std::optional<std::uint64_t> covered_pixels, stack_peak;
  std::uint64_t flash = 0, scene_data = 0, pipeline_flash = 0, ram = 0;
};

// Reads the lines; nullopt unless instructions, flash, pipeline_flash and ram are
// all there. A line with a key it does not know is ignored (newer scripts may add some).
std::optional<Measurement> read_measurement(const std::string& output);

struct MeasureSetup {
  std::filesystem::path script;  // measure_elf.sh
  std::filesystem::path plugin;  // libspanlight_icount.so
  std::string unavailable;       // why nothing can be measured; empty when it can
};

// The build tree the running binary belongs to (<build>/bin/spanlight -> <build>).
std::filesystem::path default_build_dir();
// The source tree this binary was built from, and measure_elf.sh in it.
std::filesystem::path source_dir();
std::filesystem::path default_measure_script();
// Checks for qemu-system-arm, arm-none-eabi-nm/size, the script and the plugin.
MeasureSetup find_measure_setup(const std::filesystem::path& plugin, const std::filesystem::path& script);

struct MeasureRun {
  int exit_code = -1;
  std::string log;  // everything the run printed (app log and measure lines)
  std::optional<Measurement> measurement;
};

// Runs `measure_elf.sh --cpu CPU --plugin P ELF ARGS...` in `work_dir` (the app writes its files there).
MeasureRun measure_elf(const MeasureSetup& setup, const std::string& cpu, const std::filesystem::path& elf,
                       const std::vector<std::string>& args, const std::filesystem::path& work_dir);

// Single quotes for the shell (paths may hold spaces or quotes).
std::string shell_quoted(const std::string& text);

}  // namespace spanlight::sweep
