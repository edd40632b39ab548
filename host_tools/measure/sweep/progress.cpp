#include "sweep/progress.hpp"

#include <unistd.h>

namespace spanlight::sweep {

Progress::Progress(std::FILE* out, bool quiet) : out_(out), quiet_(quiet), terminal_(isatty(fileno(out)) != 0) {}

void Progress::phase(const std::string& name, std::size_t total) {
  name_ = name;
  total_ = total;
  done_ = 0;
  last_tenth_ = 0;
  start_ = std::chrono::steady_clock::now();
  if (!quiet_) std::fprintf(out_, "%s: %zu to do\n", name_.c_str(), total_);
}

void Progress::step(const std::string& detail) {
  ++done_;
  if (quiet_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double left = done_ ? elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_) : 0.0;
  if (terminal_) {
    std::fprintf(out_, "\r\033[K  [%zu/%zu] %s (%.0f s left)", done_, total_, detail.c_str(), left);
    std::fflush(out_);
    return;
  }
  const std::size_t tenth = total_ ? done_ * 10 / total_ : 10;
  if (tenth > last_tenth_ || done_ == total_) {
    last_tenth_ = tenth;
    std::fprintf(out_, "  [%zu/%zu] %s (%.0f s elapsed, %.0f s left)\n", done_, total_, detail.c_str(), elapsed, left);
  }
}

void Progress::note(const std::string& text) {
  if (quiet_) return;
  if (terminal_) std::fprintf(out_, "\r\033[K");
  std::fprintf(out_, "%s\n", text.c_str());
}

void Progress::finish_phase() {
  if (quiet_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (terminal_) std::fprintf(out_, "\r\033[K");
  std::fprintf(out_, "%s: done in %.1f s\n", name_.c_str(), elapsed);
}

}  // namespace spanlight::sweep
