#include "json_describe.hpp"

#include <charconv>

namespace spanlight::scene::detail {
namespace {

constexpr std::size_t longest_quoted_string = 40;

std::string quoted(const std::string& text) {
  if (text.size() <= longest_quoted_string) return "\"" + text + "\"";
  return "\"" + text.substr(0, longest_quoted_string) + "...\"";
}

std::string count_of(std::size_t count, const char* singular, const char* plural) {
  return std::to_string(count) + " " + (count == 1 ? singular : plural);
}

}  // namespace

std::string describe(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return value.get<bool>() ? "true" : "false";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return format_number(value.get<double>());
    case Json::value_t::string: return quoted(value.get<std::string>());
    case Json::value_t::array: return "an array of " + count_of(value.size(), "element", "elements");
    case Json::value_t::object: return "an object";
    default: return std::string("a ") + value.type_name();
  }
}

std::string format_number(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

std::string format_vec3(const glm::dvec3& value) {
  // Appends, not "[" + ...: g++ 12 warns falsely (-Wrestrict) on literal + string temporary.
  std::string text = "[";
  text.append(format_number(value.x)).append(", ").append(format_number(value.y));
  text.append(", ").append(format_number(value.z)).append("]");
  return text;
}

}  // namespace spanlight::scene::detail
