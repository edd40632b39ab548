// Comparing a rendered picture with the expected one, pixel by pixel.
#pragma once

#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>

#include "effects_renderers.hpp"

namespace spanlight::effects {

// expected(px, py) gives the grey byte every channel must hold, or -1 where the test
// makes no claim. Returns the pixels off by more than `lsb` and describes the first few.
struct Mismatches {
  int count = 0;
  int checked = 0;
  std::string first;
};

inline Mismatches compare_grey(const Picture& picture, const std::function<int(int, int)>& expected, int lsb) {
  Mismatches m;
  std::ostringstream text;
  for (int y = 0; y < picture.height; ++y) {
    for (int x = 0; x < picture.width; ++x) {
      const int want = expected(x, y);
      if (want < 0) continue;
      ++m.checked;
      for (int c = 0; c < 3; ++c) {
        const int got = picture.channel(x, y, c);
        if (std::abs(got - want) > lsb) {
          if (m.count < 5) text << "(" << x << ", " << y << ") channel " << c << ": " << got << ", expected " << want << "; ";
          ++m.count;
          break;
        }
      }
    }
  }
  m.first = text.str();
  return m;
}

}  // namespace spanlight::effects
