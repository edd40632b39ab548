// The host's reciprocal: the same fixedpoint::reciprocal<B, S> the firmware
// instantiates, chosen at run time, so the host tools build one pipeline per
// pixel format instead of one per (table bits, Newton steps) pair. The
// results are the firmware's to the bit: the same function does the work.
#pragma once

#include <cstdint>

#include "fixedpoint/reciprocal.hpp"

namespace spanlight::prepare {

struct RuntimeReciprocal {
  static fixedpoint::Reciprocal of(std::uint32_t d);
  static std::uint32_t of_normalised(std::uint32_t m);  // m in [2^31, 2^32)
};

// Selects the table and steps RuntimeReciprocal uses on this thread while it lives.
class ReciprocalChoice {
 public:
  ReciprocalChoice(int table_bits, int newton_steps);  // throws std::invalid_argument
  ~ReciprocalChoice();
  ReciprocalChoice(const ReciprocalChoice&) = delete;
  ReciprocalChoice& operator=(const ReciprocalChoice&) = delete;

 private:
  int previous_;
};

}  // namespace spanlight::prepare
