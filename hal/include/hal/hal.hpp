// The few platform services a spanlight firmware app uses. Two implementations link
// against this one header, so an app's source is the same on both:
//   spanlight_hal_host       stdio files, stderr, std::chrono (host builds, tests)
//   spanlight_hal_cortex_m   semihosting under QEMU, timer0, the measure markers
// Nothing here allocates. The pipeline's math never includes this header.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace spanlight::hal {

// ---------------------------------------------------------------- entry and exit

// The command line: args[0] is the program name. On Cortex-M it comes from semihosting
// SYS_GET_CMDLINE split at spaces (so no argument may contain a space).
using Args = std::span<const char* const>;

// Each app defines app_main. The HAL owns the real entry point (host main, or the Cortex-M
// reset path); it calls app_main and exits with its return value.
int app_main(Args args);

// Ends the run with status (QEMU exits with it on Cortex-M).
[[noreturn]] void exit(int status);

// One line of text, newline added: stdout under QEMU (semihosting SYS_WRITE0), stderr on host.
void log_line(const char* text);

// ---------------------------------------------------------------- frame output

inline constexpr std::size_t kBytesPerPixel = 3;  // RGB888, R first

struct FrameSize {
  std::uint16_t width;
  std::uint16_t height;
};

constexpr std::size_t frame_bytes(FrameSize size) {
  return std::size_t{size.width} * size.height * kBytesPerPixel;
}

// A rectangle of the frame; a line is a rectangle of height 1.
struct Rect {
  std::uint16_t x;
  std::uint16_t y;
  std::uint16_t width;
  std::uint16_t height;
};

// Where finished pixels go: a binary PPM (P6) file, written straight from the caller's
// memory, no buffer of its own. A renderer with a whole frame calls write_frame; one that
// renders in lines or tiles calls flush_rect per piece, in any order, the way it would push
// spans to a display. Every call returns false when the host reports an error.
class FrameSink {
 public:
  FrameSink() = default;
  FrameSink(const FrameSink&) = delete;
  FrameSink& operator=(const FrameSink&) = delete;
  ~FrameSink() { (void)close(); }

  // Creates (truncates) the file and writes the PPM header.
  [[nodiscard]] bool open(const char* path, FrameSize size);
  // The whole frame: frame_bytes(size) bytes, rows top to bottom.
  [[nodiscard]] bool write_frame(std::span<const std::uint8_t> rgb);
  // One rectangle; its row r starts at rgb[r * stride_bytes]. Must lie inside the frame.
  [[nodiscard]] bool flush_rect(Rect rect, std::span<const std::uint8_t> rgb, std::size_t stride_bytes);
  // Idempotent; the destructor calls it.
  [[nodiscard]] bool close();

 private:
  std::intptr_t handle_ = -1;  // a FILE* on host, a semihosting handle on Cortex-M
  FrameSize size_{};
};

// ---------------------------------------------------------------- cost

// Brackets measured regions; elapsed() sums all of them. On Cortex-M, begin() and end() call
// the noinline marker functions spanlight_measure_begin / spanlight_measure_end, between which
// the QEMU plugin (tools/qemu_icount) counts executed instructions exactly; elapsed() is then
// timer0 ticks (25 MHz, 40 instructions per tick under -icount shift=0), a coarse cross-check.
// On host, elapsed() is steady_clock nanoseconds.
class CostCounter {
 public:
  void begin();
  void end();
  [[nodiscard]] std::uint64_t elapsed() const { return elapsed_; }
  // "ns" or "timer0-ticks".
  [[nodiscard]] static const char* unit();

 private:
  std::uint64_t start_ = 0;
  std::uint64_t elapsed_ = 0;
};

// ---------------------------------------------------------------- memory

// Deepest stack use so far in bytes, from the stack paint on Cortex-M; 0 on host (not measured).
std::size_t stack_peak_bytes();
// Forgets the peak below the caller (read stack_peak_bytes() first) and returns the stack in
// use at the caller, so that stack_peak_bytes() - stack_mark() after a call is that call's own
// depth: what render_frame needs of the stack, apart from the app around it. 0 on host.
std::size_t stack_mark();

}  // namespace spanlight::hal
