#include "sweep/grid.hpp"

#include <algorithm>
#include <stdexcept>

#include "io/knob_text.hpp"

namespace spanlight::sweep {
namespace {

constexpr std::size_t knob_count = std::size(knob_table);

std::size_t knob_index(std::string_view name) {
  for (std::size_t i = 0; i < knob_count; ++i)
    if (name == knob_table[i].name) return i;
  throw std::logic_error("no knob named " + std::string(name));
}

}  // namespace

std::string choice_list(std::string_view knob) {
  std::string list;
  for (const std::string& v : knob_choices(knob)) list += (list.empty() ? "" : ", ") + v;
  return list;
}

std::string filter_choice_list() {
  std::string list;
  for (const char* v : knob_values::filter) list += (list.empty() ? "" : ", ") + std::string(v);
  return list;
}

const char* to_string(FilterChoice filter) { return filter_choice_name(filter); }

FilterChoice filter_from_string(const std::string& text) {
  FilterChoice filter = FilterChoice::scene;
  if (!parse_filter_choice(text, filter))
    throw std::invalid_argument("texture filter: expected one of " + filter_choice_list() + ", not \"" + text + "\"");
  return filter;
}

std::string label(const GridPoint& p) {
  std::string out;
  for (const KnobInfo& info : knob_table) {
    if (std::string_view(info.name) == "format") continue;
    out += std::string(info.name) + "=" + knob_value(p.knobs, info.name) + " ";
  }
  return out + "filter=" + to_string(p.filter);
}

GridSpec default_grid() {
  GridSpec grid;
  const Knobs defaults{};
  for (const KnobInfo& info : knob_table) {
    const std::vector<std::string> all = knob_choices(info.name);
    const std::string_view name = info.name;
    std::vector<std::string> chosen;
    if (name == "span") {
      for (std::size_t i = 0; i < all.size(); i += 2) chosen.push_back(all[i]);
    } else if (name == "table-bits" || name == "depth-bits") {
      chosen = all;
    } else if (name == "newton") {
      chosen.assign(all.begin(), all.end() - 1);  // the bench's dispatch compiles all but the last
    } else {
      chosen = {knob_value(defaults, info.name)};
    }
    grid.values.push_back(chosen);
  }
  return grid;
}

void check_grid(const GridSpec& grid) {
  if (grid.values.size() != knob_count) throw std::invalid_argument("grid: expected a value list for every knob");
  for (std::size_t i = 0; i < knob_count; ++i) {
    if (grid.values[i].empty()) throw std::invalid_argument(std::string("--") + knob_table[i].name + ": expected at least one value");
    for (const std::string& value : grid.values[i]) {
      Knobs k;
      if (set_knob(k, knob_table[i].name, value) != KnobError::ok)
        throw std::invalid_argument(std::string("--") + knob_table[i].name + ": expected one of " +
                                    choice_list(knob_table[i].name) + ", not \"" + value + "\"");
    }
  }
  if (grid.filters.empty()) throw std::invalid_argument("--filters: expected at least one filter");
}

std::vector<GridPoint> expand(const GridSpec& grid) {
  check_grid(grid);
  std::vector<GridPoint> out;
  for (const FilterChoice filter : grid.filters) {
    std::vector<Knobs> partial{Knobs{}};
    for (std::size_t i = 0; i < knob_count; ++i) {
      std::vector<Knobs> next;
      for (const Knobs& k : partial)
        for (const std::string& value : grid.values[i]) {
          Knobs with = k;
          (void)set_knob(with, knob_table[i].name, value);  // checked above
          next.push_back(with);
        }
      partial = std::move(next);
    }
    for (const Knobs& k : partial) out.push_back({k, filter});
  }
  return out;
}

GridPoint cost_representative(const GridPoint& point, const GridSpec& grid) {
  GridPoint rep = point;
  const Knobs defaults{};
  for (const char* name : {"table-bits", "depth-bits"}) {
    const std::vector<std::string>& values = grid.values[knob_index(name)];
    const std::string wanted = knob_value(defaults, name);
    (void)set_knob(rep.knobs, name,
                   std::find(values.begin(), values.end(), wanted) != values.end() ? wanted : values.front());
  }
  return rep;
}

}  // namespace spanlight::sweep
