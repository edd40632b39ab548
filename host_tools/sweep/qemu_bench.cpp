#include "sweep/qemu_bench.hpp"

#include <array>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <sys/wait.h>

namespace spanlight::sweep {
namespace fs = std::filesystem;
namespace {

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return false;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    std::error_code ec;
    if (!dir.empty() && fs::exists(fs::path(dir) / program, ec)) return true;
  }
  return false;
}

// Single quotes for the shell; the arguments are ours, but paths may hold spaces.
std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The value after "key=" in a "sweep_bench: a=1 b=2" line.
std::string field(const std::string& line, const std::string& key) {
  const std::size_t at = line.find(" " + key + "=");
  if (at == std::string::npos) return {};
  const std::size_t begin = at + key.size() + 2;
  const std::size_t end = line.find(' ', begin);
  return line.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

}  // namespace

fs::path default_build_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::current_path() : exe.parent_path().parent_path();
}

fs::path default_runner() { return fs::path(SPANLIGHT_SOURCE_DIR) / "tools" / "qemu_icount" / "run_on_qemu.sh"; }

QemuSetup find_qemu(const fs::path& firmware_dir, const fs::path& runner) {
  QemuSetup s{runner, firmware_dir / "tools" / "qemu_icount" / "libspanlight_icount.so", firmware_dir, {}};
  std::error_code ec;
  if (!on_path("qemu-system-arm")) s.unavailable = "qemu-system-arm is not on PATH";
  else if (!fs::exists(runner, ec)) s.unavailable = runner.string() + " is missing";
  else if (!fs::exists(s.plugin, ec)) s.unavailable = s.plugin.string() + " is missing (build target spanlight_icount)";
  else if (!on_path("arm-none-eabi-nm")) s.unavailable = "arm-none-eabi-nm is not on PATH";
  return s;
}

fs::path bench_elf(const QemuSetup& setup, const std::string& cpu, const std::string& scene_name) {
  return setup.firmware_dir / ("firmware-" + cpu) / "bin" / ("sweep_bench_" + scene_name + ".elf");
}

std::vector<std::string> bench_arguments(const SweepConfig& c, bool passes) {
  std::vector<std::string> args{"--table-bits", std::to_string(c.table_bits), "--newton",     std::to_string(c.newton),
                                "--span",       std::to_string(c.span),       "--tolerance",  std::to_string(c.tolerance_log2),
                                "--depth-bits", std::to_string(c.depth_bits), "--fused",      c.fused ? "1" : "0",
                                "--filter",     to_string(c.filter)};
  if (passes) args.emplace_back("--passes");
  return args;
}

BenchRun run_bench(const QemuSetup& setup, const std::string& cpu, const fs::path& elf, const SweepConfig& config,
                   bool passes) {
  BenchRun run;
  std::string command = "bash " + quoted(setup.runner.string()) + " --cpu " + cpu + " --plugin " +
                        quoted(setup.plugin.string()) + " --timeout 300 " + quoted(elf.string());
  for (const std::string& a : bench_arguments(config, passes)) command += " " + a;
  command += " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    run.error = "cannot start " + setup.runner.string();
    return run;
  }
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) run.log += buffer.data();
  const int status = pclose(pipe);
  const int exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;

  bool counted = false, logged = false;
  std::stringstream lines(run.log);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("spanlight-instructions: ", 0) == 0) {
      run.instructions = std::stoull(line.substr(24));
      counted = true;
    } else if (line.rfind("spanlight-region: ", 0) == 0) {
      run.regions.push_back(std::stoull(line.substr(18)));
    } else if (line.rfind("sweep_bench: regions", 0) == 0) {
      std::stringstream names(line.substr(20));
      std::string name;
      while (names >> name) run.region_names.push_back(name);
    } else if (line.rfind("sweep_bench: scene=", 0) == 0) {
      run.hash = static_cast<std::uint32_t>(std::stoul(field(line, "hash"), nullptr, 16));
      run.format = field(line, "format");
      logged = true;
    }
  }
  if (exit_code != 0) run.error = "exit status " + std::to_string(exit_code);
  else if (!logged) run.error = "no result line from the bench";
  else if (!counted) run.error = "no instruction count from the plugin";
  run.ok = run.error.empty();
  return run;
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
