// The cost of a configuration on target: runs firmware/apps/sweep_bench in QEMU
// through tools/qemu_icount/run_on_qemu.sh with the exact instruction-count
// plugin, and reads back the count and the frame hash the bench logs.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sweep/sweep_config.hpp"

namespace spanlight::sweep {

struct QemuSetup {
  std::filesystem::path runner;        // run_on_qemu.sh
  std::filesystem::path plugin;        // libspanlight_icount.so
  std::filesystem::path firmware_dir;  // the host build tree holding firmware-<cpu>/bin
  std::string unavailable;             // why QEMU cost cannot be measured; empty when it can
};

// The build tree the running binary belongs to (<build>/bin/spanlight -> <build>).
std::filesystem::path default_build_dir();
// run_on_qemu.sh in the source tree this binary was built from.
std::filesystem::path default_runner();

// Checks for qemu-system-arm, the runner and the plugin.
QemuSetup find_qemu(const std::filesystem::path& firmware_dir, const std::filesystem::path& runner);

std::filesystem::path bench_elf(const QemuSetup& setup, const std::string& cpu, const std::string& scene_name);

struct BenchRun {
  bool ok = false;
  std::string error;                   // why not ok (exit status, missing count, ...)
  std::uint64_t instructions = 0;      // sum over the measured regions
  std::vector<std::uint64_t> regions;  // per region (per pass with `passes`)
  std::vector<std::string> region_names;
  std::uint32_t hash = 0;              // FNV-1a of the colour buffer
  std::string format;                  // the bench's pixel format, as baked
  std::string log;                     // everything the run printed
};

BenchRun run_bench(const QemuSetup& setup, const std::string& cpu, const std::filesystem::path& elf,
                   const SweepConfig& config, bool passes = false);

// The bench's arguments for a configuration (its command line after the ELF).
std::vector<std::string> bench_arguments(const SweepConfig& config, bool passes);

// FNV-1a over bytes: the bench's frame hash, computed on the host render's raw buffer.
std::uint32_t fnv1a(const std::vector<std::uint8_t>& bytes);

}  // namespace spanlight::sweep
