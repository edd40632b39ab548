#include "cli/knobs.hpp"

#include "io/knob_text.hpp"

#include <string>
#include <vector>

namespace spanlight::cli {

void add_knob_options(CLI::App& cmd, Knobs& knobs) {
  const Knobs defaults{};
  for (const KnobInfo& info : knob_table) {
    const std::string name = info.name;
    const std::vector<std::string> allowed = knob_choices(name);
    cmd.add_option_function<std::string>(
           "--" + name, [&knobs, name](const std::string& value) { (void)set_knob(knobs, name, value); }, info.help)
        ->check(CLI::IsMember(allowed))
        ->default_str(knob_value(defaults, name));
  }
}

std::vector<std::string> knob_option_names() {
  std::vector<std::string> names;
  for (const KnobInfo& info : knob_table) names.push_back(std::string("--") + info.name);
  return names;
}

}  // namespace spanlight::cli
