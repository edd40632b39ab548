// Follows the JSON parser's events to know the field path of the value being
// parsed, e.g. "objects[2].transform.scale", so that errors the parser itself
// raises (number overflow, a repeated key) can name their field.
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <vector>

namespace spanlight::scene::detail {

class JsonPathTracker {
 public:
  void start_container(bool is_array);
  void end_container();
  void end_scalar();
  // Returns false when the current object already had this key.
  bool enter_key(const std::string& key);
  // Path of the value being parsed now; "(root)" at the top.
  std::string path() const;

 private:
  struct Level {
    bool is_array = false;
    std::size_t element_index = 0;  // arrays: index of the element being parsed
    std::string key;                // objects: key of the value being parsed
    std::set<std::string> keys_seen;
  };
  void value_finished();
  std::vector<Level> levels_;
};

}  // namespace spanlight::scene::detail
