#include "cli/accuracy_warning.hpp"

#include <cstdio>

#include "fixedpoint/reciprocal_bound.hpp"

namespace spanlight::cli {
namespace {

constexpr long double largest_fine_error = 1.0L / 2048.0L;  // 2^-11: 1/8 texel at 256 texels
constexpr double coordinate = 256.0;                         // texels, as in the message

}  // namespace

std::optional<std::string> accuracy_warning(const Knobs& knobs) {
  const long double error = fixedpoint::reciprocal_error_bound(knobs.table_bits, knobs.newton);
  if (error <= largest_fine_error) return std::nullopt;
  char text[512];
  std::snprintf(text, sizeof text,
                "warning: --table-bits %d --newton %d: the per-span divide is off by up to %.1e (relative), %.2f "
                "texel at a texture coordinate of %.0f texels, so textures shift and shadow edges move (what the "
                "example scenes lose: docs/limits.md). --newton 1 with any table, or --table-bits 12, keeps it "
                "under 1/8 texel.",
                int(knobs.table_bits), int(knobs.newton), static_cast<double>(error),
                static_cast<double>(error) * coordinate, coordinate);
  return std::string(text);
}

void warn_if_inaccurate(const Knobs& knobs) {
  if (const auto warning = accuracy_warning(knobs)) std::fprintf(stderr, "%s\n", warning->c_str());
}

}  // namespace spanlight::cli
