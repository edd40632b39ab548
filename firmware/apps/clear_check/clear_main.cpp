// clear_check: pipeline/.../5_frame/clear.hpp's fill_bytes and clear_depth, which on the targets
// store words by store-multiples the host never runs (frames equal to the host's cover only the
// buffers' own sizes and alignments). Every start offset 0..3 and length 0..300 bytes of a
// buffer, and depth buffers of 0..100 entries: the bytes inside set, every byte around them
// untouched. Logs the count of wrong cases and returns 1 if there is one.
#include <cstddef>
#include <cstdint>

#include "hal/hal.hpp"
#include "hal/log_line.hpp"
#include "spanlight/5_frame/clear.hpp"

namespace {

constexpr std::size_t guard = 40;
alignas(4) std::uint8_t bytes[guard + 4 + 300 + guard];
alignas(4) std::uint32_t words[8 + 100 + 8];
alignas(4) std::uint16_t halves[8 + 100 + 8];

std::uint32_t wrong = 0, cases = 0;

void check_bytes(std::size_t offset, std::size_t n, std::uint8_t value) {
  for (std::uint8_t& b : bytes) b = 0x5A;
  spanlight::fill_bytes(bytes + guard + offset, n, value);
  bool ok = true;
  for (std::size_t i = 0; i < sizeof bytes; ++i) {
    const bool inside = i >= guard + offset && i < guard + offset + n;
    ok = ok && bytes[i] == (inside ? value : 0x5A);
  }
  wrong += !ok;
  ++cases;
}

template <typename T, std::size_t N>
void check_depth(T (&buffer)[N], std::size_t n, std::uint32_t clear) {
  for (T& d : buffer) d = static_cast<T>(0x1234);
  spanlight::clear_depth(buffer + 8, n, clear);
  bool ok = true;
  for (std::size_t i = 0; i < N; ++i) ok = ok && buffer[i] == static_cast<T>(i >= 8 && i < 8 + n ? clear : 0x1234);
  wrong += !ok;
  ++cases;
}

}  // namespace

int spanlight::hal::app_main(Args /*args*/) {
  for (std::size_t offset = 0; offset < 4; ++offset)
    for (std::size_t n = 0; n <= 300; ++n) check_bytes(offset, n, n % 2 == 0 ? 0x00 : 0xFF);
  for (std::size_t n = 0; n <= 100; ++n) {
    check_depth(words, n, 0x00FFFFFFu);  // 24-bit depth in words
    check_depth(halves, n, 0xFFFFu);     // 16-bit depth
  }
  log_line(LogLine() << "clear_check: " << cases << " cases, " << wrong << " wrong");
  return wrong == 0 ? 0 : 1;
}
