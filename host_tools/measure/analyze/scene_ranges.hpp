// What a scene asks of the fixed-point formats: the extent of every quantity
// the pipeline stores, measured in double on the scene itself (before
// prepare, so a scene prepare would refuse can still be analysed).
#pragma once

#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace spanlight::analyze {

struct Interval {
  double lo = 0.0, hi = 0.0;
  bool empty = true;
  void add(double v);
};

struct ObjectRanges {
  std::string name;
  double largest_coordinate = 0.0;  // max |x|, |y|, |z| in object space (the Q15.16 operand)
  bool textured = false;
  int texture_width = 0, texture_height = 0;
  double largest_texel = 0.0;       // max |u * width|, |v * height|
};

struct ProjectorRanges {
  std::string name;
  Interval q;                        // q over every vertex of every object
  std::size_t vertices_behind = 0;   // q <= 0: the pipeline evaluates those spans per pixel
  Interval window_depth;             // r/q over vertices in front of the projector (its shadow-map depth)
  bool shadows = false;
  double bias = 0.0;
  int map_size = 0;
};

// The eye's depth buffer: where visible surfaces lie and how close another
// object comes behind them (what a coarse depth buffer can confuse).
struct DepthRanges {
  Interval visible;                  // window depth of the visible surfaces
  std::vector<double> gaps;          // per covered pixel with a second object: its depth - the visible depth
  std::size_t covered = 0;
  // Pixels where another object lies within one depth step of the visible one at `bits`.
  std::size_t at_risk(int bits) const;
};

struct SceneRanges {
  std::vector<ObjectRanges> objects;
  std::vector<ProjectorRanges> projectors;
  Interval clip_w;                   // eye clip-space w over vertices inside near/far (after clipping)
  Interval window_x, window_y;       // pixels, after near/far clipping
  DepthRanges depth;
  double largest_coordinate = 0.0;
  double largest_texel = 0.0;
};

SceneRanges measure_ranges(const scene::Scene& scene);

}  // namespace spanlight::analyze
