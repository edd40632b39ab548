// One point of the speed/accuracy grid: every knob the sweep varies, and the
// grid itself. The knobs are the pipeline's (features.hpp Precision, the
// TableReciprocal template) plus the texture filter, which the scene decides
// unless the sweep forces it.
#pragma once

#include <string>
#include <vector>

#include "prepare/render_fixed.hpp"

namespace spanlight::sweep {

enum class FilterChoice { scene, nearest, bilinear };

struct SweepConfig {
  int span = 16;  // pixels between exact divides (a power of two)
  int tolerance_log2 = 3;
  int table_bits = 8;
  int newton = 1;
  int depth_bits = 24;
  bool fused = false;
  FilterChoice filter = FilterChoice::scene;
  friend bool operator==(const SweepConfig&, const SweepConfig&) = default;
};

// The knobs the firmware ships with (features.hpp defaults, knobs.hpp defaults).
inline SweepConfig default_config() { return {}; }

const char* to_string(FilterChoice filter);
FilterChoice filter_from_string(const std::string& text);  // throws std::invalid_argument

// "span16 tb8 n1 z24 multipass scene": unique within a grid, no commas.
std::string label(const SweepConfig& config);
// The same as `spanlight render/bake` options (filter excluded: it lives in the scene).
std::string knob_arguments(const SweepConfig& config, PixelFormat format);

int span_log2_of(int span);  // throws std::invalid_argument unless a power of two in [1, 64]
prepare::FixedOptions to_fixed_options(const SweepConfig& config, PixelFormat format);

struct GridSpec {
  std::vector<int> spans{1, 2, 4, 8, 16, 32};
  std::vector<int> tolerances{3};
  std::vector<int> table_bits{6, 8, 10, 12};
  std::vector<int> newton{0, 1};
  std::vector<int> depth_bits{16, 24};
  std::vector<FilterChoice> filters{FilterChoice::scene};
  std::vector<bool> fused{false, true};
};

// Every combination, filters outermost (one prepared scene per filter), then
// span, tolerance, table, Newton, depth, fused.
std::vector<SweepConfig> expand(const GridSpec& grid);

}  // namespace spanlight::sweep
