// measure DEADLINE_SECONDS REPORT_FILE COMMAND [ARGS...]
//
// Runs COMMAND (stdin from /dev/null, stdout and stderr its own), kills it if
// it has not ended after DEADLINE_SECONDS, and writes one line to REPORT_FILE:
//   status=S seconds=T maxrss_kib=M
// S is the exit status (124: killed at the deadline, 128+N: killed by signal N),
// T the wall time, M the peak resident memory of the command (ru_maxrss from
// wait4, KiB on Linux). Exits with S; 125 when the runner itself fails.
// The hostile-input tests (tests/hostile) use it: no /usr/bin/time needed.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

constexpr int runner_failed = 125;
constexpr int deadline_passed = 124;

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: measure DEADLINE_SECONDS REPORT_FILE COMMAND [ARGS...]\n");
    return runner_failed;
  }
  const double deadline = std::atof(argv[1]);
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = ::fork();
  if (child < 0) return runner_failed;
  if (child == 0) {
    const int null = ::open("/dev/null", O_RDONLY);
    if (null >= 0) ::dup2(null, STDIN_FILENO);
    ::execvp(argv[3], argv + 3);
    std::perror(argv[3]);
    ::_exit(127);
  }

  int status = 0;
  rusage usage{};
  bool killed = false;
  for (;;) {
    const pid_t done = ::wait4(child, &status, killed ? 0 : WNOHANG, &usage);
    if (done == child) break;
    if (done < 0) return runner_failed;
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    if (elapsed.count() > deadline) {
      ::kill(child, SIGKILL);
      killed = true;
    } else {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  const int exit_status = killed ? deadline_passed : WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);

  std::FILE* report = std::fopen(argv[2], "w");
  if (report == nullptr) return runner_failed;
  std::fprintf(report, "status=%d seconds=%.3f maxrss_kib=%ld\n", exit_status, seconds.count(), usage.ru_maxrss);
  std::fclose(report);
  return exit_status;
}
