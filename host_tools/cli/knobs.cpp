#include "cli/knobs.hpp"

namespace spanlight::cli {
namespace {

std::uint8_t log2_of(int power_of_two) {
  std::uint8_t k = 0;
  while ((1 << k) < power_of_two) ++k;
  return k;
}

}  // namespace

void add_knob_options(CLI::App& cmd, KnobArgs& knobs) {
  cmd.add_option("--span", knobs.span, "most pixels between exact perspective divides (power of two)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16, 32, 64}));
  cmd.add_option("--tolerance", knobs.tolerance_log2,
                 "shorten segments that would drift more than 2^-N texel from the exact value (0: never)")
      ->check(CLI::Range(0, 10));
  cmd.add_option("--table-bits", knobs.table_bits, "reciprocal table index bits")->check(CLI::IsMember({6, 8, 10, 12}));
  cmd.add_option("--newton", knobs.newton, "Newton-Raphson steps after the table")->check(CLI::IsMember({0, 1, 2}));
  cmd.add_option("--depth-bits", knobs.depth_bits, "depth buffer and shadow map bits")->check(CLI::IsMember({16, 24}));
  cmd.add_option("--format", knobs.format, "framebuffer format")->check(CLI::IsMember({"rgb888", "rgb565"}));
  cmd.add_flag("--fused", knobs.fused, "one fused pass instead of the paper's multipass (same bytes)");
}

prepare::FixedOptions to_fixed_options(const KnobArgs& knobs) {
  prepare::FixedOptions options;
  options.format = knobs.format == "rgb565" ? PixelFormat::rgb565 : PixelFormat::rgb888;
  options.table_bits = knobs.table_bits;
  options.newton_steps = knobs.newton;
  options.precision.span_log2 = log2_of(knobs.span);
  options.precision.span_tolerance_log2 = static_cast<std::uint8_t>(knobs.tolerance_log2);
  options.precision.depth_bits = static_cast<std::uint8_t>(knobs.depth_bits);
  options.precision.fused = knobs.fused;
  return options;
}

}  // namespace spanlight::cli
