// The format version (1 or 2) and the fields a version-1 file may not hold.
#include "scene_readers.hpp"

namespace spanlight::scene::detail {

int read_version(const JsonField& root) {
  constexpr const char* expected = "expected the format version 1 or 2";
  if (!root.has("spanlight_scene")) root.fail_member("spanlight_scene", std::string(expected) + ", got nothing: the field is missing");
  const JsonField version = root.required("spanlight_scene");
  if (!version.json().is_number()) version.fail(expected);
  const double number = version.json().get<double>();
  if (number != 1.0 && number != 2.0) version.fail(expected);
  return static_cast<int>(number);
}

void refuse_version_2_fields(const JsonField& owner, int version, std::initializer_list<std::string_view> fields) {
  if (version >= 2) return;
  for (const std::string_view field : fields) {
    if (owner.has(field)) {
      owner.fail_member(field, "expected a field of format version 1, got " + std::string(field) +
                                   ", which is new in version 2 (set \"spanlight_scene\": 2)");
    }
  }
}

}  // namespace spanlight::scene::detail
