// How field paths are spelled in errors: "objects[2].transform.scale",
// "textures.wood.image"; the document itself is "(root)".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace spanlight::scene::detail {

inline constexpr std::string_view root_field_name = "(root)";

inline std::string member_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

inline std::string element_path(const std::string& parent, std::size_t index) {
  return parent + "[" + std::to_string(index) + "]";
}

inline std::string printable_path(const std::string& path) {
  return path.empty() ? std::string(root_field_name) : path;
}

}  // namespace spanlight::scene::detail
