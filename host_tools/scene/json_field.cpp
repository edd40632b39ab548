#include "json_field.hpp"

#include <algorithm>
#include <cmath>

#include "json_describe.hpp"
#include "scene/scene.hpp"

namespace spanlight::scene::detail {
namespace {

std::string join(const std::vector<std::string_view>& names, std::string_view separator) {
  std::string text;
  for (const auto& name : names) {
    if (!text.empty()) text += separator;
    text += name;
  }
  return text;
}

}  // namespace

void JsonField::fail(const std::string& expected) const {
  throw SceneError(file_->string(), printable_path(path_), expected + ", got " + describe(*value_));
}

void JsonField::fail_with(const std::string& message) const {
  throw SceneError(file_->string(), printable_path(path_), message);
}

void JsonField::fail_member(std::string_view key, const std::string& message) const {
  throw SceneError(file_->string(), member_path(path_, key), message);
}

void JsonField::expect_object_with_fields(std::initializer_list<std::string_view> known) const {
  if (!value_->is_object()) fail("expected an object");
  for (const auto& [key, value] : value_->items()) {
    if (std::find(known.begin(), known.end(), key) == known.end()) {
      fail_member(key, "expected only the fields " + join(known, ", ") + ", got the unknown field " + key);
    }
  }
}

bool JsonField::has(std::string_view key) const {
  return value_->is_object() && value_->contains(key);
}

JsonField JsonField::required(std::string_view key) const {
  if (!value_->is_object()) fail("expected an object");
  if (!value_->contains(key)) fail_member(key, "expected a value (the field is required), got nothing: the field is missing");
  return JsonField(value_->at(key), member_path(path_, key), *file_);
}

std::optional<JsonField> JsonField::optional(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return required(key);
}

std::vector<std::pair<std::string, JsonField>> JsonField::members() const {
  if (!value_->is_object()) fail("expected an object");
  std::vector<std::pair<std::string, JsonField>> members;
  for (const auto& [key, value] : value_->items()) {
    members.emplace_back(key, JsonField(value, member_path(path_, key), *file_));
  }
  return members;
}

std::vector<JsonField> JsonField::elements() const {
  if (!value_->is_array()) fail("expected an array");
  std::vector<JsonField> elements;
  for (std::size_t i = 0; i < value_->size(); ++i) {
    elements.emplace_back((*value_)[i], element_path(path_, i), *file_);
  }
  return elements;
}

std::vector<JsonField> JsonField::elements(std::size_t count, std::string_view what_elements) const {
  if (!value_->is_array() || value_->size() != count) {
    fail("expected an array of " + std::string(what_elements));
  }
  return elements();
}

double JsonField::number(const NumberRange& range) const {
  // Non-finite numbers cannot come from JSON text (the parser rejects 1e999),
  // but the check keeps "finite" true of every number a Scene holds.
  if (!value_->is_number() || !std::isfinite(value_->get<double>())) fail("expected " + range.description);
  const double value = value_->get<double>();
  if (!range.contains(value)) fail("expected " + range.description);
  return value;
}

std::int64_t JsonField::integer(std::int64_t low, std::int64_t high, std::string_view meaning) const {
  std::string expected = "expected an integer in " + std::to_string(low) + ".." + std::to_string(high);
  if (!meaning.empty()) expected += " (" + std::string(meaning) + ")";
  if (!value_->is_number()) fail(expected);
  const double value = value_->get<double>();
  // Compare as doubles first: casting an out-of-range double to an integer is undefined.
  if (!(value >= static_cast<double>(low) && value <= static_cast<double>(high)) || value != std::floor(value)) {
    fail(expected);
  }
  return static_cast<std::int64_t>(value);
}

std::string JsonField::string() const { return string_or_fail("expected a string"); }

std::string JsonField::string_or_fail(const std::string& expected) const {
  if (!value_->is_string()) fail(expected);
  return value_->get<std::string>();
}

glm::dvec3 JsonField::vec3(const NumberRange& range) const {
  const auto xyz = elements(3, "3 numbers");
  return {xyz[0].number(range), xyz[1].number(range), xyz[2].number(range)};
}

glm::dvec2 JsonField::vec2(const NumberRange& range) const {
  const auto uv = elements(2, "2 numbers");
  return {uv[0].number(range), uv[1].number(range)};
}

glm::dvec4 JsonField::vec4(const NumberRange& range) const {
  const auto abcd = elements(4, "4 numbers");
  return {abcd[0].number(range), abcd[1].number(range), abcd[2].number(range), abcd[3].number(range)};
}

bool JsonField::boolean() const {
  if (!value_->is_boolean()) fail("expected true or false");
  return value_->get<bool>();
}

std::string JsonField::choice_description(const std::vector<std::string_view>& names) {
  return "expected one of " + join(names, ", ");
}

}  // namespace spanlight::scene::detail
