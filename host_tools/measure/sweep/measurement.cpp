#include "sweep/measurement.hpp"

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

}  // namespace

std::optional<Measurement> read_measurement(const std::string& output) {
  Measurement m;
  bool instructions = false, flash = false, pipeline = false, ram = false;
  std::istringstream lines(output);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string tag, key;
    if (!(words >> tag >> key) || tag != "spanlight-measure:") continue;
    std::vector<std::uint64_t> values;
    for (std::string w; words >> w;) {
      if (w.find_first_not_of("0123456789") != std::string::npos || w.size() > 19) return std::nullopt;
      values.push_back(std::stoull(w));
    }
    if (key == "regions") {
      m.regions = values;
      continue;
    }
    if (values.size() != 1) return std::nullopt;
    const std::uint64_t v = values[0];
    if (key == "instructions") m.instructions = v, instructions = true;
    else if (key == "covered_pixels") m.covered_pixels = v;
    else if (key == "stack_peak") m.stack_peak = v;
    else if (key == "flash") m.flash = v, flash = true;
    else if (key == "scene_data") m.scene_data = v;
    else if (key == "pipeline_flash") m.pipeline_flash = v, pipeline = true;
    else if (key == "ram") m.ram = v, ram = true;
  }
  if (!instructions || !flash || !pipeline || !ram) return std::nullopt;
  return m;
}

fs::path default_build_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::current_path() : exe.parent_path().parent_path();
}

fs::path source_dir() { return fs::path(SPANLIGHT_SOURCE_DIR); }

fs::path default_measure_script() { return source_dir() / "tools" / "qemu_icount" / "measure_elf.sh"; }

MeasureSetup find_measure_setup(const fs::path& plugin, const fs::path& script) {
  MeasureSetup s{script, plugin, {}};
  std::error_code ec;
  if (!on_path("qemu-system-arm")) s.unavailable = "qemu-system-arm is not on PATH";
  else if (!on_path("arm-none-eabi-nm") || !on_path("arm-none-eabi-size")) s.unavailable = "arm-none-eabi-nm or -size is not on PATH";
  else if (!fs::exists(script, ec)) s.unavailable = script.string() + " is missing";
  else if (!fs::exists(plugin, ec)) s.unavailable = plugin.string() + " is missing (build target spanlight_icount)";
  return s;
}

std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

MeasureRun measure_elf(const MeasureSetup& setup, const std::string& cpu, const fs::path& elf,
                       const std::vector<std::string>& args, const fs::path& work_dir) {
  MeasureRun run;
  // Word by word: "literal" + string&& trips GCC 12's false -Wrestrict (PR 105651).
  std::string command = "cd";
  auto word = [&](const std::string& w) {
    command += ' ';
    command += w;
  };
  for (const std::string& w : {shell_quoted(work_dir.string()), std::string("&& bash"), shell_quoted(setup.script.string()),
                               std::string("--cpu"), shell_quoted(cpu), std::string("--plugin"),
                               shell_quoted(setup.plugin.string()), shell_quoted(elf.string())})
    word(w);
  for (const std::string& a : args) word(shell_quoted(a));
  command += " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return run;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) run.log += buffer.data();
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.measurement = read_measurement(run.log);
  return run;
}

}  // namespace spanlight::sweep
