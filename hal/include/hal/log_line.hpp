// A fixed-capacity text line for hal::log_line: builds "name: 42 ticks" without printf
// (newlib's printf allocates) and without the heap. Text past the capacity is dropped.
#pragma once

#include "hal/hal.hpp"

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>

namespace spanlight::hal {

// Wraps a value to print as 0x%08x.
struct Hex {
  std::uint32_t value;
};

template <std::size_t Capacity = 160>
class LogLine {
 public:
  LogLine() { text_[0] = '\0'; }

  LogLine& operator<<(const char* text) {
    while (*text != '\0') {
      put(*text++);
    }
    return *this;
  }

  LogLine& operator<<(std::string_view text) {
    for (const char c : text) {
      put(c);
    }
    return *this;
  }

  template <std::integral T>
  LogLine& operator<<(T value) {
    if constexpr (std::is_signed_v<T>) {
      if (value < 0) {
        put('-');
        // Negate in unsigned arithmetic: -INT_MIN does not fit the signed type.
        return append_unsigned(0u - static_cast<std::uint64_t>(value));
      }
    }
    return append_unsigned(static_cast<std::uint64_t>(value));
  }

  LogLine& operator<<(Hex hex) {
    static constexpr char kDigits[] = "0123456789abcdef";
    *this << "0x";
    for (int shift = 28; shift >= 0; shift -= 4) {
      put(kDigits[(hex.value >> shift) & 0xFu]);
    }
    return *this;
  }

  [[nodiscard]] const char* c_str() const { return text_; }

 private:
  LogLine& append_unsigned(std::uint64_t value) {
    char reversed[20];  // 2^64 has 20 decimal digits
    std::size_t count = 0;
    do {
      reversed[count++] = static_cast<char>('0' + value % 10u);
      value /= 10u;
    } while (value != 0u);
    while (count > 0) {
      put(reversed[--count]);
    }
    return *this;
  }

  void put(char c) {
    if (length_ + 1 < Capacity) {
      text_[length_++] = c;
      text_[length_] = '\0';
    }
  }

  char text_[Capacity];
  std::size_t length_ = 0;
};

}  // namespace spanlight::hal

namespace spanlight::hal {

// log_line(LogLine() << "x = " << x): logs a built line.
template <std::size_t Capacity>
void log_line(const LogLine<Capacity>& line) {
  log_line(line.c_str());
}

}  // namespace spanlight::hal
