#include "prepare/render_fixed.hpp"

namespace spanlight::prepare {

FixedFrame render_fixed(const PreparedStorage& prepared, const Knobs& knobs) {
  return render_fixed_with_hooks(prepared, knobs, NoHooks{});
}

FixedFrame render_fixed(const PreparedStorage& prepared, const FrameMatrices& matrices, const Knobs& knobs) {
  return render_fixed_with_hooks(prepared, matrices, knobs, NoHooks{});
}

const char* to_string(PixelFormat format) { return knob_value(Knobs{.format = format}, "format"); }

}  // namespace spanlight::prepare
