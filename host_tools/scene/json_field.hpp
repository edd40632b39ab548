// A JSON value together with its field path and file: every typed read
// checks type and range and, on failure, throws SceneError(file, path,
// "expected ..., got ...").
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "field_path.hpp"
#include "json_document.hpp"
#include "number_range.hpp"

namespace spanlight::scene::detail {

class JsonField {
 public:
  JsonField(const Json& value, std::string path, const std::filesystem::path& file)
      : value_(&value), path_(std::move(path)), file_(&file) {}

  const Json& json() const { return *value_; }
  const std::string& path() const { return path_; }
  const std::filesystem::path& file() const { return *file_; }

  // Throws SceneError with "<expected>, got <what this field holds>".
  [[noreturn]] void fail(const std::string& expected) const;
  // Throws SceneError with this message as it is ("expected ..., got ...").
  [[noreturn]] void fail_with(const std::string& message) const;
  // Throws SceneError for a field of this object, present or not.
  [[noreturn]] void fail_member(std::string_view key, const std::string& message) const;

  // Objects. expect_object_with_fields: an object holding no key outside known.
  void expect_object_with_fields(std::initializer_list<std::string_view> known) const;
  bool has(std::string_view key) const;
  JsonField required(std::string_view key) const;
  std::optional<JsonField> optional(std::string_view key) const;
  std::vector<std::pair<std::string, JsonField>> members() const;

  // Arrays. what_elements names the elements in the message ("3 numbers").
  std::vector<JsonField> elements() const;
  std::vector<JsonField> elements(std::size_t count, std::string_view what_elements) const;

  // Scalars.
  double number(const NumberRange& range = any_number()) const;
  // An integral value (320 or 320.0) in [low, high].
  std::int64_t integer(std::int64_t low, std::int64_t high, std::string_view meaning = {}) const;
  std::string string() const;
  glm::dvec3 vec3(const NumberRange& range = any_number()) const;
  glm::dvec2 vec2(const NumberRange& range = any_number()) const;
  glm::dvec4 vec4(const NumberRange& range = any_number()) const;
  bool boolean() const;

  // One of a fixed set of names, e.g. {{"nearest", Filter::nearest}, ...}.
  template <typename Enum>
  Enum choice(std::initializer_list<std::pair<std::string_view, Enum>> options) const {
    const std::string name = string_or_fail(choice_description(names_of(options)));
    for (const auto& [option_name, option] : options) {
      if (name == option_name) return option;
    }
    fail(choice_description(names_of(options)));
  }

 private:
  template <typename Enum>
  static std::vector<std::string_view> names_of(std::initializer_list<std::pair<std::string_view, Enum>> options) {
    std::vector<std::string_view> names;
    for (const auto& option : options) names.push_back(option.first);
    return names;
  }
  static std::string choice_description(const std::vector<std::string_view>& names);
  std::string string_or_fail(const std::string& expected) const;

  const Json* value_;
  std::string path_;
  const std::filesystem::path* file_;
};

}  // namespace spanlight::scene::detail
