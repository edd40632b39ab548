// Shared by the demo apps: a number from the command line without the C library.
#pragma once

#include <cstdint>

namespace spanlight::apps {

// `text` as a decimal integer in [min, max] (digits only); false otherwise.
constexpr bool parse_count(const char* text, std::uint32_t min, std::uint32_t max, std::uint32_t& value) {
  if (text == nullptr || *text == 0) return false;
  std::uint32_t n = 0;
  for (const char* c = text; *c != 0; ++c) {
    if (*c < '0' || *c > '9' || n > max) return false;
    n = n * 10 + static_cast<std::uint32_t>(*c - '0');
  }
  if (n < min || n > max) return false;
  value = n;
  return true;
}

}  // namespace spanlight::apps
