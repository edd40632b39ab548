#include "sweep/sweep_config.hpp"

#include <stdexcept>

namespace spanlight::sweep {

const char* to_string(FilterChoice filter) {
  switch (filter) {
    case FilterChoice::scene: return "scene";
    case FilterChoice::nearest: return "nearest";
    case FilterChoice::bilinear: return "bilinear";
  }
  return "scene";
}

FilterChoice filter_from_string(const std::string& text) {
  if (text == "scene") return FilterChoice::scene;
  if (text == "nearest") return FilterChoice::nearest;
  if (text == "bilinear") return FilterChoice::bilinear;
  throw std::invalid_argument("texture filter must be scene, nearest or bilinear, not \"" + text + "\"");
}

std::string label(const SweepConfig& c) {
  std::string out = "span" + std::to_string(c.span);
  if (c.tolerance_log2 != 3) out += " tol" + std::to_string(c.tolerance_log2);
  out += " tb" + std::to_string(c.table_bits) + " n" + std::to_string(c.newton) + " z" + std::to_string(c.depth_bits);
  out += c.fused ? " fused " : " multipass ";
  return out + to_string(c.filter);
}

std::string knob_arguments(const SweepConfig& c, PixelFormat format) {
  std::string out = "--span " + std::to_string(c.span) + " --tolerance " + std::to_string(c.tolerance_log2) +
                    " --table-bits " + std::to_string(c.table_bits) + " --newton " + std::to_string(c.newton) +
                    " --depth-bits " + std::to_string(c.depth_bits) + " --format " + prepare::to_string(format);
  if (c.fused) out += " --fused";
  return out;
}

int span_log2_of(int span) {
  for (int k = 0; k <= 6; ++k)
    if ((1 << k) == span) return k;
  throw std::invalid_argument("span must be a power of two from 1 to 64, not " + std::to_string(span));
}

prepare::FixedOptions to_fixed_options(const SweepConfig& c, PixelFormat format) {
  prepare::FixedOptions o;
  o.format = format;
  o.table_bits = c.table_bits;
  o.newton_steps = c.newton;
  o.precision.span_log2 = static_cast<std::uint8_t>(span_log2_of(c.span));
  o.precision.span_tolerance_log2 = static_cast<std::uint8_t>(c.tolerance_log2);
  o.precision.depth_bits = static_cast<std::uint8_t>(c.depth_bits);
  o.precision.fused = c.fused;
  return o;
}

std::vector<SweepConfig> expand(const GridSpec& g) {
  std::vector<SweepConfig> out;
  for (FilterChoice filter : g.filters)
    for (int span : g.spans)
      for (int tolerance : g.tolerances)
        for (int table : g.table_bits)
          for (int newton : g.newton)
            for (int depth : g.depth_bits)
              for (bool fused : g.fused) out.push_back({span, tolerance, table, newton, depth, fused, filter});
  return out;
}

}  // namespace spanlight::sweep
