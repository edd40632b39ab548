// What main() needs from the board: somewhere to send the finished frame, and a way to stop.
// board_semihosting.cpp implements both for any Cortex-M under a debugger or QEMU; a product
// replaces it with its display driver.
#pragma once

#include <cstdint>

// rgb565: width * height pixels, row 0 at the top. True when the whole frame went out.
bool board_send_frame(const std::uint16_t* rgb565, std::uint16_t width, std::uint16_t height);

// Ends the run with status (0: success).
[[noreturn]] void board_stop(int status);
