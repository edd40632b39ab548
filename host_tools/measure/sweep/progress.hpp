// Progress on stderr while a sweep runs: one self-overwriting line on a
// terminal, otherwise a line at every tenth of a phase (readable in logs).
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <string>

namespace spanlight::sweep {

class Progress {
 public:
  explicit Progress(std::FILE* out = stderr, bool quiet = false);
  void phase(const std::string& name, std::size_t total);
  void step(const std::string& detail);  // one unit of the current phase done
  void note(const std::string& text);     // a line of its own
  void finish_phase();

 private:
  std::FILE* out_;
  bool quiet_, terminal_;
  std::string name_;
  std::size_t total_ = 0, done_ = 0, last_tenth_ = 0;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace spanlight::sweep
