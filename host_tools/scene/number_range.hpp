// The allowed values of a number field and how a message states them:
// "a number in (0, 180)", "a number >= 0", "a number > near (0.5)".
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace spanlight::scene::detail {

struct NumberRange {
  struct Bound {
    double value;
    bool inclusive;
  };
  std::optional<Bound> low, high;
  std::string description;

  bool contains(double value) const;
};

NumberRange any_number();
NumberRange open_interval(double low, double high);    // (low, high)
NumberRange closed_interval(double low, double high);  // [low, high]
NumberRange greater_than(double low);                  // > low
NumberRange at_least(double low);                      // >= low
// > another field's value, named in the message: "a number > near (0.5)".
NumberRange greater_than_field(double low, std::string_view field_name);

}  // namespace spanlight::scene::detail
