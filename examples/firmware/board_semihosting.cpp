// The frame leaves the board as frame.ppm, written on the debugger's host through Arm
// semihosting: QEMU (-semihosting) and OpenOCD (`arm semihosting enable`) both do it. Without a
// debugger attached, the bkpt instruction below stops the core: replace this file for a product.
#include <array>
#include <cstdint>
#include <cstring>

#include "board.hpp"
#include "spanlight/4_pixel/colour.hpp"  // ColorTraits: RGB565 -> RGB888 exactly as the host tools do

namespace {

enum : std::uint32_t { sys_open = 0x01, sys_close = 0x02, sys_write = 0x05, sys_exit_extended = 0x20 };
constexpr std::uint32_t open_write_binary = 5;          // fopen mode "wb"
constexpr std::uint32_t application_exit = 0x20026;     // ADP_Stopped_ApplicationExit

// r0 = operation, r1 = its parameter block; the result comes back in r0.
std::int32_t semihost(std::uint32_t operation, const void* block) {
  register std::uint32_t r0 __asm__("r0") = operation;
  register const void* r1 __asm__("r1") = block;
  __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return static_cast<std::int32_t>(r0);
}

std::uint32_t word(const void* pointer) { return reinterpret_cast<std::uintptr_t>(pointer); }

bool write(std::int32_t handle, const void* data, std::size_t length) {
  const std::uint32_t block[3] = {static_cast<std::uint32_t>(handle), word(data), length};
  return semihost(sys_write, block) == 0;  // the count of bytes not written
}

// Writes value in decimal at out; returns the end.
char* append_decimal(char* out, std::uint32_t value) {
  char digits[10];
  int count = 0;
  do {
    digits[count++] = static_cast<char>('0' + value % 10);
    value /= 10;
  } while (value != 0);
  while (count > 0) *out++ = digits[--count];
  return out;
}

}  // namespace

bool board_send_frame(const std::uint16_t* rgb565, std::uint16_t width, std::uint16_t height) {
  static std::array<std::uint8_t, 3 * 1024> row;  // one RGB888 row at a time
  if (width > row.size() / 3) return false;
  static const char name[] = "frame.ppm";
  const std::uint32_t open_block[3] = {word(name), open_write_binary, sizeof name - 1};
  const std::int32_t handle = semihost(sys_open, open_block);
  if (handle == -1) return false;

  // "P6\n<width> <height>\n255\n", then the rows as RGB888.
  char header[32] = "P6\n";
  char* end = append_decimal(header + 3, width);
  *end++ = ' ';
  end = append_decimal(end, height);
  std::memcpy(end, "\n255\n", 5);
  bool ok = write(handle, header, static_cast<std::size_t>(end + 5 - header));

  using Rgb565 = spanlight::ColorTraits<spanlight::PixelFormat::rgb565>;
  for (std::uint32_t y = 0; ok && y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      const spanlight::Colour c = Rgb565::load(rgb565 + y * width + x);
      row[3 * x] = static_cast<std::uint8_t>(spanlight::red(c));
      row[3 * x + 1] = static_cast<std::uint8_t>(spanlight::green(c));
      row[3 * x + 2] = static_cast<std::uint8_t>(spanlight::blue(c));
    }
    ok = write(handle, row.data(), 3u * width);
  }
  const std::uint32_t close_block[1] = {static_cast<std::uint32_t>(handle)};
  return semihost(sys_close, close_block) == 0 && ok;
}

void board_stop(int status) {
  const std::uint32_t block[2] = {application_exit, static_cast<std::uint32_t>(status)};
  semihost(sys_exit_extended, block);
  for (;;) {
  }
}
