// One number as printf writes it, for reports, tables and plots, so no caller
// keeps a buffer of its own. Header only: every host library may use it.
#pragma once

#include <cstdio>
#include <string>

namespace spanlight::io {

// number_text("%.2f", 3.14159) == "3.14". `pattern` takes exactly one double;
// the text is cut at 63 characters (no report number comes near).
inline std::string number_text(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

}  // namespace spanlight::io
