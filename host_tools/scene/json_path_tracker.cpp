#include "json_path_tracker.hpp"

#include "field_path.hpp"

namespace spanlight::scene::detail {

void JsonPathTracker::start_container(bool is_array) {
  Level level;
  level.is_array = is_array;
  levels_.push_back(std::move(level));
}

void JsonPathTracker::end_container() {
  levels_.pop_back();
  value_finished();
}

void JsonPathTracker::end_scalar() { value_finished(); }

bool JsonPathTracker::enter_key(const std::string& key) {
  Level& object = levels_.back();
  object.key = key;
  return object.keys_seen.insert(key).second;
}

std::string JsonPathTracker::path() const {
  std::string path;
  for (const Level& level : levels_) {
    if (level.is_array) {
      path = element_path(path, level.element_index);
    } else if (!level.key.empty()) {
      path = member_path(path, level.key);
    }
  }
  return printable_path(path);
}

// A finished value moves an enclosing array on to its next element.
void JsonPathTracker::value_finished() {
  if (!levels_.empty() && levels_.back().is_array) {
    ++levels_.back().element_index;
  }
}

}  // namespace spanlight::scene::detail
