#include "number_range.hpp"

#include "json_describe.hpp"

namespace spanlight::scene::detail {

bool NumberRange::contains(double value) const {
  if (low && (low->inclusive ? value < low->value : value <= low->value)) return false;
  if (high && (high->inclusive ? value > high->value : value >= high->value)) return false;
  return true;
}

NumberRange any_number() { return {std::nullopt, std::nullopt, "a number"}; }

NumberRange open_interval(double low, double high) {
  return {NumberRange::Bound{low, false}, NumberRange::Bound{high, false},
          "a number in (" + format_number(low) + ", " + format_number(high) + ")"};
}

NumberRange closed_interval(double low, double high) {
  return {NumberRange::Bound{low, true}, NumberRange::Bound{high, true},
          "a number in [" + format_number(low) + ", " + format_number(high) + "]"};
}

NumberRange greater_than(double low) {
  return {NumberRange::Bound{low, false}, std::nullopt, "a number > " + format_number(low)};
}

NumberRange at_least(double low) {
  return {NumberRange::Bound{low, true}, std::nullopt, "a number >= " + format_number(low)};
}

NumberRange greater_than_field(double low, std::string_view field_name) {
  return {NumberRange::Bound{low, false}, std::nullopt,
          "a number > " + std::string(field_name) + " (" + format_number(low) + ")"};
}

}  // namespace spanlight::scene::detail
