// The speed/accuracy grid: a point is the pipeline's Knobs (spanlight/knobs.hpp,
// the one knob vocabulary) plus the texture filter, which the scene decides
// unless the sweep forces it. The grid names each knob's values as typed, so
// options, CSV columns and knob-config files all go through set_knob.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "spanlight/knobs.hpp"

namespace spanlight::sweep {

struct GridPoint {
  Knobs knobs{};
  FilterChoice filter = FilterChoice::scene;
  friend bool operator==(const GridPoint&, const GridPoint&) = default;
};

// FilterChoice and its names are knobs.hpp's (the bench parses them too).
const char* to_string(FilterChoice filter);
FilterChoice filter_from_string(const std::string& text);  // throws std::invalid_argument

// "span=16 tolerance=5 table-bits=8 newton=1 depth-bits=24 passes=fused filter=scene":
// unique within a grid (whose format is one), no commas.
std::string label(const GridPoint& point);

// "1, 2, 4, ...": a knob's allowed values for messages.
std::string choice_list(std::string_view knob);

// "scene, nearest, bilinear": the filter choices for messages.
std::string filter_choice_list();

// Each knob's values (knob_table's order and names) and the filters.
struct GridSpec {
  std::vector<std::vector<std::string>> values;  // one list per knob_table entry, values as typed
  std::vector<FilterChoice> filters{FilterChoice::scene};
};

// The default grid, from knob_table: every other span, each table size, Newton
// 0 and 1 (what the bench compiles), both depth settings; the default
// tolerance, format and passes (the multipass renders the same bytes).
// 4 x 4 x 2 x 2 = 64 points a filter.
GridSpec default_grid();

// Throws std::invalid_argument naming the knob and value unless every value is one
// set_knob takes and no list is empty.
void check_grid(const GridSpec& grid);

// Every combination, filters outermost (one prepared scene per filter), then the
// knobs in knob_table's order.
std::vector<GridPoint> expand(const GridSpec& grid);

// The point whose instruction count stands for `point` when QEMU runs only the
// cost-relevant grid: table bits and depth bits at their defaults where the grid has them.
GridPoint cost_representative(const GridPoint& point, const GridSpec& grid);

}  // namespace spanlight::sweep
