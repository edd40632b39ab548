// The knobs as text, every form made from the one knob_table (spanlight/knobs.hpp):
// command-line words for the bench and the CLI, one line for reports and baked
// configurations, and each knob's allowed values for option checks and grids.
// Header only, beside io/number_text.hpp: the text forms every host tool shares.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "spanlight/knobs.hpp"

namespace spanlight {

// {"--span", "64", "--tolerance", "5", ...}: every knob, in knob_table's order.
inline std::vector<std::string> knob_arguments(const Knobs& knobs) {
  std::vector<std::string> words;
  for (const KnobInfo& info : knob_table) {
    words.push_back(std::string("--") + info.name);
    words.emplace_back(knob_value(knobs, info.name));
  }
  return words;
}

// "--span 64 --tolerance 5 ...": the same words as one line, as `spanlight render` takes them.
inline std::string knob_command_line(const Knobs& knobs) {
  std::string line;
  for (const std::string& word : knob_arguments(knobs)) line += (line.empty() ? "" : " ") + word;
  return line;
}

// The allowed values of knob `name` as typed ({} for an unknown name).
inline std::vector<std::string> knob_choices(std::string_view name) {
  for (const KnobInfo& info : knob_table)
    if (name == info.name) return {info.values, info.values + info.value_count};
  return {};
}

}  // namespace spanlight
