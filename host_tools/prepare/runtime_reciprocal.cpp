#include "prepare/runtime_reciprocal.hpp"

#include <stdexcept>

namespace spanlight::prepare {
namespace {

using Function = fixedpoint::Reciprocal (*)(std::uint32_t);
using NormalisedFunction = std::uint32_t (*)(std::uint32_t);

template <int B, int S>
fixedpoint::Reciprocal reciprocal_of(std::uint32_t d) {
  return fixedpoint::reciprocal<B, S>(d);
}

// Index: table (6, 8, 10, 12 -> 0..3) * 3 + Newton steps.
constexpr Function choices[] = {
    reciprocal_of<6, 0>,  reciprocal_of<6, 1>,  reciprocal_of<6, 2>,  reciprocal_of<8, 0>,
    reciprocal_of<8, 1>,  reciprocal_of<8, 2>,  reciprocal_of<10, 0>, reciprocal_of<10, 1>,
    reciprocal_of<10, 2>, reciprocal_of<12, 0>, reciprocal_of<12, 1>, reciprocal_of<12, 2>,
};
constexpr NormalisedFunction normalised_choices[] = {
    fixedpoint::reciprocal_normalised<6, 0>,  fixedpoint::reciprocal_normalised<6, 1>,
    fixedpoint::reciprocal_normalised<6, 2>,  fixedpoint::reciprocal_normalised<8, 0>,
    fixedpoint::reciprocal_normalised<8, 1>,  fixedpoint::reciprocal_normalised<8, 2>,
    fixedpoint::reciprocal_normalised<10, 0>, fixedpoint::reciprocal_normalised<10, 1>,
    fixedpoint::reciprocal_normalised<10, 2>, fixedpoint::reciprocal_normalised<12, 0>,
    fixedpoint::reciprocal_normalised<12, 1>, fixedpoint::reciprocal_normalised<12, 2>,
};

thread_local int current_choice = 4;  // 8-bit table, one Newton step: the default knobs

}  // namespace

fixedpoint::Reciprocal RuntimeReciprocal::of(std::uint32_t d) { return choices[current_choice](d); }
std::uint32_t RuntimeReciprocal::of_normalised(std::uint32_t m) { return normalised_choices[current_choice](m); }

ReciprocalChoice::ReciprocalChoice(int table_bits, int newton_steps) : previous_(current_choice) {
  if (table_bits != 6 && table_bits != 8 && table_bits != 10 && table_bits != 12)
    throw std::invalid_argument("reciprocal table bits must be 6, 8, 10 or 12");
  if (newton_steps < 0 || newton_steps > 2) throw std::invalid_argument("newton steps must be 0, 1 or 2");
  current_choice = (table_bits - 6) / 2 * 3 + newton_steps;
}

ReciprocalChoice::~ReciprocalChoice() { current_choice = previous_; }

}  // namespace spanlight::prepare
