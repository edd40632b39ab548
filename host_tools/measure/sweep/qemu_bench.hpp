// The cost of a grid point on target: runs firmware/apps/sweep_bench through
// measure_elf.sh (the one measuring path) and reads back the count, the region
// names and the frame hash the bench logs.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sweep/grid.hpp"
#include "sweep/measurement.hpp"

namespace spanlight::sweep {

std::filesystem::path bench_elf(const std::filesystem::path& build_dir, const std::string& cpu, const std::string& scene_name);

struct BenchRun {
  bool ok = false;
  std::string error;                   // why not ok (exit status, missing count, ...)
  std::uint64_t instructions = 0;      // sum over the measured regions
  std::vector<std::uint64_t> regions;  // per region (per pass with `per_pass`)
  std::vector<std::string> region_names;
  std::uint32_t hash = 0;              // FNV-1a of the colour buffer
  std::string format;                  // the bench's pixel format, as baked
  std::string log;                     // everything the run printed
};

// The bench's command line after the ELF: every knob as `spanlight render` takes it,
// then --filter and, for per-pass counts, --per-pass.
std::vector<std::string> bench_arguments(const GridPoint& point, bool per_pass);

// Reads a bench run's output (its log and the measure lines) into a BenchRun.
BenchRun read_bench_run(const std::string& output, int exit_code);

BenchRun run_bench(const MeasureSetup& setup, const std::string& cpu, const std::filesystem::path& elf,
                   const GridPoint& point, bool per_pass = false);

// FNV-1a over bytes: the bench's frame hash, computed on the host render's raw buffer.
std::uint32_t fnv1a(const std::vector<std::uint8_t>& bytes);

}  // namespace spanlight::sweep
