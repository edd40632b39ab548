#include "sweep/qemu_bench.hpp"

#include <sstream>

#include "io/knob_text.hpp"

namespace spanlight::sweep {
namespace fs = std::filesystem;
namespace {

// The value after "key=" in a "sweep_bench: a=1 b=2" line.
std::string field(const std::string& line, const std::string& key) {
  const std::size_t at = line.find(" " + key + "=");
  if (at == std::string::npos) return {};
  const std::size_t begin = at + key.size() + 2;
  const std::size_t end = line.find_first_of(" ,", begin);
  return line.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

}  // namespace

fs::path bench_elf(const fs::path& build_dir, const std::string& cpu, const std::string& scene_name) {
  return build_dir / ("firmware-" + cpu) / "bin" / ("sweep_bench_" + scene_name + ".elf");
}

std::vector<std::string> bench_arguments(const GridPoint& point, bool per_pass) {
  std::vector<std::string> args = knob_arguments(point.knobs);
  args.insert(args.end(), {"--filter", to_string(point.filter)});
  if (per_pass) args.emplace_back("--per-pass");
  return args;
}

BenchRun read_bench_run(const std::string& output, int exit_code) {
  BenchRun run;
  run.log = output;
  bool logged = false;
  std::stringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("sweep_bench: regions", 0) == 0) {
      std::stringstream names(line.substr(20));
      for (std::string name; names >> name;) run.region_names.push_back(name);
    } else if (line.rfind("sweep_bench: scene=", 0) == 0) {
      try {
        run.hash = static_cast<std::uint32_t>(std::stoul(field(line, "hash"), nullptr, 16));
        logged = true;
      } catch (const std::exception&) {
      }
      run.format = field(line, "format");
    }
  }
  const std::optional<Measurement> m = read_measurement(output);
  if (m) {
    run.instructions = m->instructions;
    run.regions = m->regions;
  }
  if (exit_code != 0) run.error = "exit status " + std::to_string(exit_code);
  else if (!logged) run.error = "no result line from the bench";
  else if (!m) run.error = "no measurement from measure_elf.sh";
  run.ok = run.error.empty();
  return run;
}

BenchRun run_bench(const MeasureSetup& setup, const std::string& cpu, const fs::path& elf, const GridPoint& point,
                   bool per_pass) {
  const MeasureRun run = measure_elf(setup, cpu, elf, bench_arguments(point, per_pass), fs::temp_directory_path());
  return read_bench_run(run.log, run.exit_code);
}

std::uint32_t fnv1a(const std::vector<std::uint8_t>& bytes) {
  std::uint32_t h = 2166136261u;
  for (std::uint8_t b : bytes) {
    h ^= b;
    h *= 16777619u;
  }
  return h;
}

}  // namespace spanlight::sweep
